#ifndef shadelab_app_Inputs_h
#define shadelab_app_Inputs_h
/**
 * @file Inputs.h
 * @brief Loading what subcommands share: meshes, scenes, option overrides,
 * and writing images, each turning failures into one-line shadelab::Errors.
 */

#include "shadelab/OutOfMemory.h"
#include "shadelab/Scene.h"

#include <vtkSmartPointer.h>

#include <new>
#include <string>
#include <utility>
#include <vector>

class slScene;
class vtkImageData;
class vtkPolyData;

namespace shadelab
{
namespace app
{
class CommandLine;
struct OptionSpec;

/// A std::bad_alloc that names the step of a command that ran out of memory
/// ("reading", "in slPolyDataNormals", "writing out.vtp"): runOnMesh()
/// (MeshJobs.h) puts it in its line.
class OutOfMemory : public std::bad_alloc
{
public:
  explicit OutOfMemory(std::string step)
    : Step(std::move(step))
  {
  }
  const char* what() const noexcept override { return "out of memory"; }
  const std::string& step() const { return this->Step; }

private:
  std::string Step;
};

/// Runs @p work, the step @p step of a command, and returns what it returns:
/// an exception it throws that says memory ran out (isOutOfMemory())
/// becomes an OutOfMemory naming @p step (one that names an inner step
/// already is passed on as it is).
template <class Work>
decltype(auto) inStep(const std::string& step, Work&& work)
{
  try
  {
    return std::forward<Work>(work)();
  }
  catch (const OutOfMemory&)
  {
    throw;
  }
  catch (const std::exception& e)
  {
    if (!isOutOfMemory(e))
    {
      throw;
    }
    throw OutOfMemory(step);
  }
}

/// The mesh formats loadMesh() reads, as one phrase for help and messages.
const char* meshFormatsText();

/// Reads a mesh with slMeshReader. Throws shadelab::Error ("FILE: problem").
vtkSmartPointer<vtkPolyData> loadMesh(const std::string& path);

/// The --scene option of every subcommand that reads a scene.
OptionSpec sceneOption();

/// Reads a scene file, or returns the built-in default scene for "".
/// Throws shadelab::Error ("FILE: KEY.PATH: problem").
vtkSmartPointer<slScene> loadScene(const std::string& path);

/// Every model's name (LightingTables.h), comma-separated.
std::string modelNameList();

/// The help of --model: what it does and every model's name.
std::string modelOptionHelp();

/// The lighting model named by option --@p option; UsageError listing the
/// valid names otherwise.
ShadingModel parseModelOption(const std::string& option, const std::string& value);

/// The lighting models named by option --@p option as "A,B,..." (or every
/// model, in the table's order, for "all" when @p allowAll); UsageError
/// naming the first unknown one otherwise.
std::vector<ShadingModel> parseModelList(const std::string& option, const std::string& value, bool allowAll);

/// Applies --model, --frequency and the material numbers (MaterialOptions.h)
/// given on @p cl. Throws UsageError for unknown names and values out of range.
void applySceneOverrides(const CommandLine& cl, slScene* scene);

/// Before drawing @p mesh (read from @p path) with @p scene's model through
/// the lighting pass, which would draw an anisotropic model in a made-up
/// frame: throws shadelab::Error ("PATH: the ward model is anisotropic and
/// needs tangents ...") if the model needs tangents @p mesh does not have
/// (a scene with a .brdf file draws that BRDF instead: no check).
void checkTangentsFor(slScene* scene, vtkPolyData* mesh, const std::string& path);
/// The same check for drawing @p mesh with @p model.
void checkTangentsFor(ShadingModel model, vtkPolyData* mesh, const std::string& path);

/// Throws shadelab::Error "--light: light K is out of range: FILE has
/// N lights" (the scene file of --scene, or the built-in scene) unless
/// @p scene has light @p light; -1 (every light) passes. Exit status 1: only
/// the scene can tell.
void checkLightOption(const CommandLine& cl, int light, slScene* scene);

/// --light of a command whose filter takes -1 by default (every light, or
/// the first with a direction): -1 when not given, else the index, checked
/// by checkLightOption(). A given -1 is a UsageError: --light names one.
int lightOption(const CommandLine& cl, slScene* scene);

/// Parses "WxH", each in [kMinImageSize, kMaxImageSize] (SceneLimits.h, the
/// range of a scene's imageSize and of a panel). Throws UsageError.
void parseSize(const std::string& text, int& width, int& height);

/// The --compress option of every subcommand that writes meshes.
OptionSpec meshCompressionOption();

/// Writes a mesh all-or-nothing (VTP, VTK, PLY, OBJ, STL), VTP compressed
/// as --compress of @p cl says. Throws shadelab::Error.
void writeMesh(vtkPolyData* mesh, const std::string& path, const CommandLine& cl);

/// Writes an image all-or-nothing. Throws shadelab::Error.
void writeImage(vtkImageData* image, const std::string& path);

/// Throws shadelab::Error as a write would ("PATH: cannot create output
/// file: REASON") unless a file can be created beside each of @p paths (its
/// folder exists and takes new files). A command that writes several files
/// asks first: each write is all-or-nothing, but a later one failing would
/// leave the earlier ones replaced.
void checkOutputsCanBeCreated(const std::vector<std::string>& paths);

} // namespace app
} // namespace shadelab

#endif
