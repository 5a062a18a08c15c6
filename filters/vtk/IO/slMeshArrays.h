#ifndef slMeshArrays_h
#define slMeshArrays_h
/**
 * @file slMeshArrays.h
 * @brief A polygon mesh, with any lines and vertex cells, as plain arrays:
 * what ShadeLab's own OBJ and PLY parsers fill without VTK (slOBJFormat.h,
 * slPLYFormat.h); slMeshArraysVTK.h turns it into vtkPolyData. Internal to
 * ShadeLab::IO.
 */

#include <cstddef>
#include <cstdint>
#include <vector>

struct slMeshArrays
{
  std::vector<float> points;          ///< x, y, z per point
  std::vector<float> normals;         ///< nx, ny, nz per point, or empty
  std::vector<float> tcoords;         ///< u, v per point, or empty
  /// Point colours (PLY), colourComponents values 0-255 per point, or empty.
  std::vector<unsigned char> colours;
  int colourComponents = 0; ///< 3 (RGB) or 4 (RGBA) with colours
  std::vector<std::int64_t> offsets;  ///< polygon k is connectivity[offsets[k], offsets[k+1])
  /// The polygons' point ids, then the lines', then the vertex cells' (one
  /// array: renumbering the points renumbers them all).
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> lineSizes;   ///< points per line (OBJ "l"), or empty
  std::vector<std::int64_t> vertexSizes; ///< points per vertex cell (OBJ "p"), or empty
};

/// Values of a float or double array, read as double (what a writer sees).
struct slValuesView
{
  const void* data = nullptr; ///< null: no such array
  bool isDouble = false;
  double operator[](std::size_t i) const
  {
    return this->isDouble ? static_cast<const double*>(this->data)[i]
                          : static_cast<double>(static_cast<const float*>(this->data)[i]);
  }
};

/// Indices stored as 32- or 64-bit integers (vtkCellArray keeps either).
struct slIndicesView
{
  const void* data = nullptr;
  bool is64 = true;
  std::int64_t operator[](std::size_t i) const
  {
    return this->is64 ? static_cast<const std::int64_t*>(this->data)[i]
                      : static_cast<std::int64_t>(static_cast<const std::int32_t*>(this->data)[i]);
  }
};

/// A polygon mesh to write, viewed in place: points, optional point normals,
/// texture coordinates and colours, and the polygons' offsets (polygons + 1
/// of them) and connectivity.
struct slMeshView
{
  std::int64_t numberOfPoints = 0;
  std::int64_t numberOfPolygons = 0;
  slValuesView points, normals, tcoords;
  const unsigned char* colours = nullptr; ///< RGB or RGBA per point (0-255), or null
  int colourComponents = 0;               ///< 3 or 4 with colours
  slIndicesView offsets, connectivity;
};

#endif
