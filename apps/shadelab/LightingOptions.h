#ifndef shadelab_app_LightingOptions_h
#define shadelab_app_LightingOptions_h
/**
 * @file LightingOptions.h
 * @brief What the lighting subcommands (cosine, light, lobe, reference)
 * share: their common options, loading a mesh with point normals, setting up
 * an slLitFilter from a scene, and running a filter into a one-line error.
 */

#include "CommandLine.h"
#include "MeshJobs.h"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class slLitFilter;
class slScene;
class vtkAlgorithm;
class vtkPolyData;

namespace shadelab
{
namespace app
{

/// --scene, --model, --allow-zero-normals, -o, --help.
std::vector<OptionSpec> litOptions();

/// Reads MESH and gives it point normals if it has none (slPolyDataNormals:
/// no splitting, so the arrays line up with MESH's points; seams welded).
vtkSmartPointer<vtkPolyData> loadMeshWithNormals(const std::string& path);

/// Scene (with --model) and --allow-zero-normals onto @p filter; returns the scene.
vtkSmartPointer<slScene> configureLitFilter(const CommandLine& cl, slLitFilter* filter);

/// Updates @p filter; throws shadelab::Error with its one-line message on failure,
/// "input mesh" replaced by @p meshPath.
void runLitFilter(slLitFilter* filter, const std::string& meshPath);

/// Before any work: --image names an image file and is given for one MESH
/// of @p jobs only; --fields is given only with --image (it chooses what the
/// image shows). Throws UsageError.
void checkFieldImageOptions(const CommandLine& cl, const std::vector<MeshJob>& jobs);

/// With --image FILE: renders the arrays named by --fields (comma-separated,
/// default @p defaultFields) of @p mesh colour-mapped with scalar bars and the
/// scene's lights as glyphs (slFieldImageRenderer) and writes FILE. Call it
/// before writing the mesh to @p meshOutput, which it first checks can be
/// created: a failed rendering, or a mesh output that cannot be made, then
/// leaves nothing written.
void writeFieldImageIfAsked(const CommandLine& cl, vtkPolyData* mesh, slScene* scene, const std::string& defaultFields,
  const std::string& meshOutput);

} // namespace app
} // namespace shadelab

#endif
