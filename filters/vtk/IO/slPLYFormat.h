#ifndef slPLYFormat_h
#define slPLYFormat_h
/**
 * @file slPLYFormat.h
 * @brief ShadeLab's own PLY parser and formatter, without VTK, for the
 * layouts vtkPLYWriter and most tools write, binary and ASCII. Internal to
 * ShadeLab::IO.
 *
 * The parser declines every other file, which slMeshReader then gives to
 * the file checks and vtkPLYReader: so a file gives the same mesh, or the
 * same one-line problem, either way.
 */

#include "ShadeLabIOModule.h"
#include "slMeshArrays.h"

#include <cstddef>
#include <string>

/// Fills @p mesh from the @p size bytes at @p bytes exactly as vtkPLYReader
/// 9.1 reads them: points, point normals, texture coordinates, colours (3
/// or 4 per point, which VTK's reader names "RGB" or "RGBA") and polygons.
/// Returns false, leaving @p mesh unspecified, unless
/// - the file is ASCII or binary PLY of either byte order, whose header
///   lines end in "\n" or "\r\n" and hold no other control byte but tabs;
/// - its header, "comment" and "obj_info" lines aside, holds "format ascii
///   1.0", "format binary_little_endian 1.0" or "format binary_big_endian
///   1.0", then an element "vertex"
///   whose properties, in any order, are float or double (float32,
///   float64) x, y, z, optionally nx, ny, nz and u, v (each stored as a
///   float, a double converted to the nearest one, as vtkPLYReader stores
///   it; a double beyond the largest float, or NaN, declines a binary
///   file), optionally uchar (uint8) red, green,
///   blue with or without alpha (each set whole or not at all), each name
///   once, and any others of any scalar type (not lists, not
///   diffuse_red, diffuse_green, diffuse_blue, texture_u or texture_v,
///   which vtkPLYReader reads in some files), which vtkPLYReader ignores
///   and the parser skips; then an element "face" with one property, a
///   list of vertex_indices or vertex_index (count uchar, indices int or
///   uint);
/// - every face has 3 or more indices naming existing vertices;
/// - a binary file ends with the last face;
/// - an ASCII file holds a row per line, each ending in a newline and of at
///   most 4000 bytes, its values parted by spaces and tabs, every value
///   decimal (floats read to the nearest double and then converted to
///   float, as VTK's PLY code reads them, finite and no range error;
///   indices and colours of digits only, colours at most 255), and nothing
///   after the last row but blank lines.
/// An ASCII file's lines are parsed on @p threads threads (at least one).
SHADELABIO_EXPORT bool slParsePLY(const char* bytes, std::size_t size, slMeshArrays& mesh, int threads);

/// Appends @p mesh as binary little-endian PLY to @p out: vertex properties
/// float x, y, z, then nx, ny, nz and u, v, and uchar red, green, blue
/// (alpha) if the mesh has them, then faces as "list uchar int
/// vertex_indices". Returns false, appending nothing, if a polygon has more
/// than 255 corners (VTK's PLY reader reads no more) or the host is
/// big-endian.
SHADELABIO_EXPORT bool slFormatPLY(const slMeshView& mesh, std::string& out);

#endif
