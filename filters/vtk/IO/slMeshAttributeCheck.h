#ifndef slMeshAttributeCheck_h
#define slMeshAttributeCheck_h
/**
 * @file slMeshAttributeCheck.h
 * @brief The check that the attribute arrays ShadeLab's filters read hold
 * finite values, whatever format the mesh came from. Internal to
 * ShadeLab::IO.
 *
 * A NaN or infinite normal, texture coordinate or tangent goes through the
 * filters into their output ("vn inf 0 0", NaN tangents), which ShadeLab's
 * own readers then reject. slMeshReader runs this check on every mesh it
 * reads, after the format's own check (which names the line where it can).
 * Other arrays (scalars, vectors, field data) are passed through as they
 * are: NaN is a usual "missing value" there, and no filter reads them.
 * The text formats' checks use slNonFiniteTextProblem() for the same
 * values, so that their message names the line.
 */

#include <string>

class vtkPolyData;

/// "" or the first value that is not finite among the point and cell
/// data's active normals, texture coordinates and tangents, and the point
/// array "Tangents" (which the filters look up by name). The problem names
/// the array, the tuple and the value, e.g.
/// `point normals array "Normals", tuple 1: inf is not a finite number`.
std::string slNonFiniteAttributeProblem(vtkPolyData* mesh);

/// For the text checks, which name the line: "" or the problem with the
/// number @p token (already known to parse with strtod) as a value VTK reads
/// into a float (@p asFloat) or a double: `"nan" is not a finite number`,
/// or `"1e39" is beyond the range of float` (VTK would read infinity, or
/// fail).
std::string slNonFiniteTextProblem(const std::string& token, bool asFloat);

#endif
