#ifndef slConnectivityCheck_h
#define slConnectivityCheck_h
/**
 * @file slConnectivityCheck.h
 * @brief The check every ShadeLab filter makes before it follows a cell's
 * point ids: each id of each vertex, line, polygon and strip cell names a
 * point of the mesh, each cell array's offsets are consistent, and every
 * point and cell data array holds a tuple for each point and cell.
 *
 * A vtkPolyData built in memory (or read by a reader that copies indices
 * unchecked) can name points that do not exist, or carry normals shorter
 * than its points; the algorithms index per-point arrays by these ids, so
 * one bad id or one short array would read or write outside them. Longer
 * arrays are left alone: they are read no further than the mesh. C++ only,
 * not wrapped.
 */

#include "ShadeLabCommonModule.h"

#include <vtkType.h>

#include <string>

class vtkDataSetAttributes;
class vtkPolyData;

/// "" when every cell of @p mesh names only points in [0, number of points),
/// its offsets are consistent and no point or cell data array is shorter
/// than the points or cells (null and empty meshes pass); otherwise one line
/// naming the first bad cell or array, e.g. "polygon 4 names point 9, but
/// the mesh has 3 points (0 to 2)", or "point array "Normals" has 3 tuples
/// for 50 points".
SHADELABCOMMON_EXPORT std::string slConnectivityProblem(vtkPolyData* mesh);

/// slConnectivityProblem(), with @p polygonIds false leaving the polygons'
/// point ids unread (their offsets are still checked): for a caller that
/// checks each id before it follows it, and asks slConnectivityProblem(mesh)
/// for the line when one is bad.
SHADELABCOMMON_EXPORT std::string slConnectivityProblem(vtkPolyData* mesh, bool polygonIds);

/// "" or the first array of @p data (a mesh's point or cell data, @p kind
/// "point" or "cell") with fewer tuples than the mesh's @p items, or, with
/// @p exact, another number: "point array "Normals" has 3 tuples for 50
/// points". slConnectivityProblem() asks for fewer (longer arrays are read no
/// further than the mesh); a reader asks for exactly as many.
SHADELABCOMMON_EXPORT std::string slArrayLengthProblem(
  vtkDataSetAttributes* data, vtkIdType items, const char* kind, bool exact);

#endif
