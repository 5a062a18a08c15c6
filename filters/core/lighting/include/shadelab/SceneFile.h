#ifndef shadelab_SceneFile_h
#define shadelab_SceneFile_h
/**
 * @file SceneFile.h
 * @brief Reading and writing JSON scene files with strict validation.
 *
 * The format is documented in docs/scene-format.md and, machine-readably, in
 * scene.schema.json, which the build generates from SceneKeys.h. Reading rejects malformed JSON, duplicate and
 * unknown keys, wrong types and out-of-range values, each with one line of the
 * form `FILE: KEY.PATH: problem` (or `FILE:LINE:COLUMN: problem` for syntax).
 */

#include "shadelab/Error.h"
#include "shadelab/Scene.h"

#include <string>

namespace shadelab
{

/// Parse scene JSON text. @p fileName is used in messages and to resolve
/// relative texture paths. Throws shadelab::Error.
Scene parseScene(const std::string& jsonText, const std::string& fileName);

/// Read and parse a scene file. Throws shadelab::Error (also for unreadable files).
Scene readSceneFile(const std::string& path);

/// The scene as JSON text that parseScene() reads back to an equal scene.
std::string sceneToJson(const Scene& scene);

/// Write sceneToJson() to @p path through a temporary file and a rename, so
/// an existing file is never left half-written. Throws shadelab::Error.
void writeSceneFile(const Scene& scene, const std::string& path);

} // namespace shadelab

#endif
