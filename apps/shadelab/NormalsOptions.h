#ifndef shadelab_app_NormalsOptions_h
#define shadelab_app_NormalsOptions_h
/**
 * @file NormalsOptions.h
 * @brief What `shadelab normals`, `tangents` and `detail` share: the normals
 * options, and running a filter with its error turned into a shadelab::Error.
 */

#include "CommandLine.h"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class slPolyDataNormals;
class slPolyDataFilter;
class vtkPolyData;

namespace shadelab
{
namespace app
{

/// --weighting, --feature-angle, --no-split, --no-consistency, --outward, --weld.
std::vector<OptionSpec> normalsOptionSpecs();

/// Configures @p filter from the options above. Throws UsageError.
void applyNormalsOptions(const CommandLine& cl, slPolyDataNormals* filter);

/// Updates @p filter (fed with the mesh read from @p meshPath) and returns a
/// copy of its output. Throws shadelab::Error("MESH: problem") if it reports an error.
vtkSmartPointer<vtkPolyData> runMeshFilter(slPolyDataFilter* filter, const std::string& meshPath);

/// Prints "shadelab CMD: note: ..." when @p mesh has vertex or line cells.
void noteNonPolygonCells(vtkPolyData* mesh, const std::string& command, const std::string& meshPath);

} // namespace app
} // namespace shadelab

#endif
