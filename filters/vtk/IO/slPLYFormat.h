#ifndef slPLYFormat_h
#define slPLYFormat_h
/**
 * @file slPLYFormat.h
 * @brief ShadeLab's own binary PLY parser and formatter, without VTK, for
 * the layout vtkPLYWriter and most tools write. Internal to ShadeLab::IO.
 *
 * The parser declines every other file, which slMeshReader then gives to
 * the file checks and vtkPLYReader: so a file gives the same mesh, or the
 * same one-line problem, either way.
 */

#include "ShadeLabIOModule.h"
#include "slMeshArrays.h"

#include <cstddef>
#include <string>

/// Fills @p mesh from the @p size bytes at @p bytes, as vtkPLYReader reads
/// them. Returns false, leaving @p mesh unspecified, unless the file is
/// binary little-endian PLY (on a little-endian host) whose header has no
/// control byte but newlines and tabs and, "comment" and "obj_info" lines
/// aside, an element "vertex" of float properties
/// x, y, z and optionally nx, ny, nz and u, v (in any order), then an
/// element "face" with one property, a list of vertex_indices (count uchar,
/// indices int or uint), every face of 3 or more indices naming existing
/// vertices, and nothing after the last face.
SHADELABIO_EXPORT bool slParsePLY(const char* bytes, std::size_t size, slMeshArrays& mesh);

/// Appends @p mesh as binary little-endian PLY to @p out: vertex properties
/// float x, y, z, then nx, ny, nz and u, v, and uchar red, green, blue
/// (alpha) if the mesh has them, then faces as "list uchar int
/// vertex_indices". Returns false, appending nothing, if a polygon has more
/// than 255 corners (VTK's PLY reader reads no more) or the host is
/// big-endian.
SHADELABIO_EXPORT bool slFormatPLY(const slMeshView& mesh, std::string& out);

#endif
