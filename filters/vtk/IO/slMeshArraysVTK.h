#ifndef slMeshArraysVTK_h
#define slMeshArraysVTK_h
/**
 * @file slMeshArraysVTK.h
 * @brief Between slMeshArrays / slMeshView and vtkPolyData: the thin VTK
 * side of ShadeLab's own OBJ and PLY parsers and formatters. Internal to
 * ShadeLab::IO.
 */

#include "slMeshArrays.h"

class vtkPolyData;

/// Fills @p output with @p mesh: float points, polygons, lines and vertex
/// cells, and the point arrays "RGB" or "RGBA" (active scalars, unsigned
/// char, first), "TCoords" and "Normals" (active texture coordinates and
/// normals) when present, the last two added in the order @p tcoordsFirst
/// says (the order of the VTK reader being stood in for). Frees @p mesh's
/// arrays as it goes.
void slToPolyData(slMeshArrays& mesh, bool tcoordsFirst, vtkPolyData* output);

/// Views @p mesh for a formatter: its points, active point normals (3
/// components), texture coordinates (2) and colours (active point scalars
/// of 3 or 4 unsigned chars), and polygons. False if the mesh has anything
/// else a VTK writer would write (vertices, lines, strips, other active
/// scalars) or values neither float nor double.
bool slViewOf(vtkPolyData* mesh, slMeshView& view);

#endif
