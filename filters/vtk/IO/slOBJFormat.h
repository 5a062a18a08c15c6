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
  /// The names of the texture coordinate arrays, one per name of a
  /// "usemtl" line, else "TCoords", in vtkOBJReader's order (that of its
  /// std::unordered_map), the first one active. Empty without texture
  /// coordinates.
  std::vector<std::string> tcoordsNames;
  /// Which of those arrays hold a point's texture coordinates (the mesh's);
  /// the others hold (-1, -1) for it: tcoordsSets[s][a] tells whether array
  /// a is in set s, the point's set is pointTCoordsSets[point], or, where
  /// that is empty (two sets at most), 0 if its texture coordinates are
  /// (-1, -1) and 1 otherwise. Set 0 holds no array.
  std::vector<std::vector<bool>> tcoordsSets;
  std::vector<std::int32_t> pointTCoordsSets;
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
/// reads them: float values; one point per vertex when every corner's vt and
/// vn index, where it has one, equals its v index, else one per corner and
/// per "l" and "p" corner; texture coordinates (-1, -1) where no face corner
/// gives one. vtkOBJReader gives an array of texture coordinates per
/// material name, holding those that faces of that material give and
/// (-1, -1) elsewhere: @p mesh holds the texture coordinates, @p attributes
/// which array holds which point's (slOBJTCoordsArray). If @p merge, points
/// equal in position, normal and every such array are then merged (as
/// slMergeIdenticalPoints merges vtkOBJReader's points, first occurrence
/// first). @p attributes also gets what vtkOBJReader makes of groups and
/// materials. Unlike vtkOBJReader 9.1 it keeps every face and "l" and "p"
/// element, and leaves out the normals when some point would have none (see
/// docs/mesh-io.md).
/// Returns false, leaving @p mesh and @p attributes unspecified, unless the
/// text (after a UTF-8 byte order mark, which is skipped) consists only of
/// blank lines, comments, "v x y z" lines (with any further numbers, such
/// as a colour, which are dropped as vtkOBJReader drops them), "vt u v",
/// "vn x y z" lines, "f" lines
/// of 3 or more corners of one form each (v, v/vt, v//vn or v/vt/vn),
/// "l" lines of 2 or more v or v/vt corners and "p" lines of v corners,
/// with positive indices naming existing values, "o", "s" and "g" lines,
/// "mtllib" lines and "usemtl" lines naming a material (of at most 99
/// bytes), with at least one face, finite decimal numbers, lines of at most
/// 1000 bytes, vt (vn) lines only if faces use them, no material named
/// "Normals" if faces have vt, and no "l" or "p" element beside materials.
/// Parses on @p threads threads (at least one).
SHADELABIO_EXPORT bool slParseOBJ(
  const char* text, std::size_t size, bool merge, slMeshArrays& mesh, slOBJAttributes& attributes, int threads);

/// Writes texture coordinate array @p a (of attributes.tcoordsNames) of
/// @p points points to @p out (2 floats per point, which may be
/// @p tcoords): a point's texture coordinates @p tcoords where the array
/// holds them, (-1, -1) elsewhere. @p attributes are those slParseOBJ gave
/// with the mesh whose texture coordinates @p tcoords are.
SHADELABIO_EXPORT void slOBJTCoordsArray(
  const slOBJAttributes& attributes, std::size_t a, const float* tcoords, std::size_t points, float* out);

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
