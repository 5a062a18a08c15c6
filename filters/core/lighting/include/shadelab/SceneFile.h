#ifndef shadelab_SceneFile_h
#define shadelab_SceneFile_h
/**
 * @file SceneFile.h
 * @brief Reading and writing JSON scene files with strict validation.
 *
 * The format is documented in docs/scene-format.md and, machine-readably, in
 * data/schema/scene.schema.json. Reading rejects malformed JSON, duplicate and
 * unknown keys, wrong types and out-of-range values, each with one line of the
 * form `FILE: KEY.PATH: problem` (or `FILE:LINE:COLUMN: problem` for syntax).
 */

#include "shadelab/Scene.h"

#include <stdexcept>
#include <string>

namespace shadelab
{

/// Thrown for any invalid scene; what() is the one-line message.
class SceneError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// Parse scene JSON text. @p fileName is used in messages and to resolve
/// relative texture paths. Throws SceneError.
Scene parseScene(const std::string& jsonText, const std::string& fileName);

/// Read and parse a scene file. Throws SceneError (also for unreadable files).
Scene readSceneFile(const std::string& path);

/// The scene as JSON text that parseScene() reads back to an equal scene.
std::string sceneToJson(const Scene& scene);

/// Write sceneToJson() to @p path through a temporary file and a rename, so
/// an existing file is never left half-written. Throws SceneError.
void writeSceneFile(const Scene& scene, const std::string& path);

} // namespace shadelab

#endif
