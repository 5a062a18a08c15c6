#ifndef slOBJFormat_h
#define slOBJFormat_h
/**
 * @file slOBJFormat.h
 * @brief ShadeLab's own OBJ parser and formatter, without VTK: vtkOBJReader
 * and vtkOBJWriter take several seconds for a mesh of a few million
 * triangles. Internal to ShadeLab::IO.
 *
 * The parser takes OBJ as it is commonly written and declines anything else,
 * which slMeshReader then gives to the file checks and vtkOBJReader: so a
 * file gives the same mesh, or the same one-line problem, either way.
 */

#include "ShadeLabIOModule.h"
#include "slMeshArrays.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

/// What vtkOBJReader 9.1 makes of a file's "g", "usemtl" and "mtllib" lines
/// besides points and cells (docs/mesh-io.md).
struct slOBJAttributes
{
  /// The texture coordinates' name: the one material's that "usemtl" names,
  /// else "TCoords".
  std::string tcoordsName = "TCoords";
  /// The cell array "GroupIds" (float), a value per polygon: the number of
  /// "g" lines before it, less one if one comes before the first face.
  /// Empty when every polygon's is 0 (as in a file without "g" lines).
  std::vector<float> groupIds;
  /// The cell array "MaterialIds" (int), a value per polygon, and the field
  /// data "MaterialNames" (by id) and "MaterialLibraries" (the first word of
  /// every "mtllib" line, if any); all empty without materials.
  std::vector<std::int32_t> materialIds;
  std::vector<std::string> materialNames, materialLibraries;
};

/// Fills @p mesh from @p size bytes of OBJ text at @p text as vtkOBJReader
/// reads them (float values; one point per vertex when every corner's vt and
/// vn index, where it has one, equals its v index, else one per corner and
/// per "l" and "p" corner; texture coordinates (-1, -1) where no face corner
/// gives one), followed, if
/// @p merge, by the merging of points equal in position, normal and texture
/// coordinate (slMergeIdenticalPoints, first occurrence first), and
/// @p attributes with what vtkOBJReader makes of groups and materials. Unlike
/// vtkOBJReader 9.1 it keeps every face and "l" and "p" element, and leaves
/// out the normals when some point would have none (see docs/mesh-io.md).
/// Returns false, leaving @p mesh and @p attributes unspecified, unless the
/// text (after a UTF-8 byte order mark, which is skipped) consists only of
/// blank lines, comments, "v x y z", "vt u v", "vn x y z" lines, "f" lines
/// of 3 or more corners of one form each (v, v/vt, v//vn or v/vt/vn),
/// "l" lines of 2 or more v or v/vt corners and "p" lines of v corners,
/// with positive indices naming existing values, "o", "s" and "g" lines,
/// "mtllib" lines and "usemtl" lines naming a material (of at most 99
/// bytes), with at least one face, finite decimal numbers, lines of at most
/// 1000 bytes, vt (vn) lines only if faces use them, one material name at
/// most (not "Normals") if faces have vt, and no "l" or "p" element beside
/// materials. Parses on @p threads threads (at least one).
SHADELABIO_EXPORT bool slParseOBJ(
  const char* text, std::size_t size, bool merge, slMeshArrays& mesh, slOBJAttributes& attributes, int threads);

/// Formats @p mesh as OBJ text: "v", then "vn" and "vt" lines if the mesh
/// has them, each value with the fewest digits that read back to the same
/// float (double for double arrays), then one "f" line per polygon whose
/// corners name the same index for v, vt and vn. Formats on @p threads
/// threads and calls @p sink(data, size) on the calling thread with the
/// text in order, piece by piece (a few MB each), while the others format
/// the next pieces. An exception from @p sink stops the formatting and is
/// rethrown.
SHADELABIO_EXPORT void slFormatOBJ(
  const slMeshView& mesh, const std::function<void(const char*, std::size_t)>& sink, int threads);

#endif
