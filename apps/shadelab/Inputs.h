#ifndef shadelab_app_Inputs_h
#define shadelab_app_Inputs_h
/**
 * @file Inputs.h
 * @brief Loading what subcommands share: meshes, scenes, option overrides,
 * and writing images, each turning failures into one-line shadelab::Errors.
 */

#include "shadelab/Scene.h"

#include <vtkSmartPointer.h>

#include <string>

class slScene;
class vtkImageData;
class vtkPolyData;

namespace shadelab
{
namespace app
{
class CommandLine;
struct OptionSpec;

/// The mesh formats loadMesh() reads, as one phrase for help and messages.
const char* meshFormatsText();

/// Reads a mesh with slMeshReader. Throws shadelab::Error ("FILE: problem").
vtkSmartPointer<vtkPolyData> loadMesh(const std::string& path);

/// Reads a scene file, or returns the built-in default scene for "".
/// Throws shadelab::Error ("FILE: KEY.PATH: problem").
vtkSmartPointer<slScene> loadScene(const std::string& path);

/// The help of --model: what it does and every model's name (LightingTables.h).
std::string modelOptionHelp();

/// The lighting model named by option --@p option; UsageError listing the
/// valid names otherwise.
ShadingModel parseModelOption(const std::string& option, const std::string& value);

/// Applies --model and --frequency. Throws UsageError for unknown names.
void applySceneOverrides(const CommandLine& cl, slScene* scene);

/// Parses "WxH" (16..8192 each). Throws UsageError.
void parseSize(const std::string& text, int& width, int& height);

/// The --compress option of every subcommand that writes meshes.
OptionSpec meshCompressionOption();

/// Writes a mesh all-or-nothing (VTP, VTK, PLY, OBJ, STL), VTP compressed
/// as --compress of @p cl says. Throws shadelab::Error.
void writeMesh(vtkPolyData* mesh, const std::string& path, const CommandLine& cl);

/// Writes an image all-or-nothing. Throws shadelab::Error.
void writeImage(vtkImageData* image, const std::string& path);

} // namespace app
} // namespace shadelab

#endif
