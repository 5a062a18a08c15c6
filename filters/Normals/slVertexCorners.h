#ifndef slVertexCorners_h
#define slVertexCorners_h
/**
 * @file slVertexCorners.h
 * @brief For every point, the polygon corners at it (a compressed sparse row
 * table). VTK-free. Internal to ShadeLab::Normals.
 *
 * Corners are positions in the connectivity array, stored as 32-bit integers:
 * meshes with 2^31 or more corners are refused by the callers.
 */

#include "slNormalsParallel.h"

#include <cstdint>
#include <vector>

namespace slnormals
{

template <typename Id>
struct VertexCorners
{
  std::vector<int32_t> offsets;    ///< numPoints + 1
  std::vector<int32_t> corners;    ///< connectivity positions, grouped by point
  std::vector<int32_t> cornerFace; ///< polygon of each position (empty if all triangles)
  bool allTriangles = false;

  int64_t faceOf(int64_t corner) const
  {
    return this->allTriangles ? corner / 3 : this->cornerFace[static_cast<size_t>(corner)];
  }

  void build(const Polygons<Id>& polys, int64_t numPoints, const Parallel& parallel)
  {
    const int64_t numCorners = polys.numPolygons ? polys.end(polys.numPolygons - 1) : 0;
    this->allTriangles = numCorners == 3 * polys.numPolygons;
    if (!this->allTriangles)
    {
      this->cornerFace.resize(static_cast<size_t>(numCorners));
      parallel.forRange(0, polys.numPolygons, 8192, [&](int64_t b, int64_t e) {
        for (int64_t f = b; f < e; ++f)
        {
          for (int64_t c = polys.begin(f); c < polys.end(f); ++c)
          {
            this->cornerFace[static_cast<size_t>(c)] = static_cast<int32_t>(f);
          }
        }
      });
    }
    else
    {
      this->cornerFace.clear();
    }
    this->offsets.assign(static_cast<size_t>(numPoints + 1), 0);
    const Id* conn = polys.connectivity;
    for (int64_t c = 0; c < numCorners; ++c)
    {
      ++this->offsets[static_cast<size_t>(conn[c]) + 1];
    }
    for (int64_t v = 0; v < numPoints; ++v)
    {
      this->offsets[static_cast<size_t>(v + 1)] += this->offsets[static_cast<size_t>(v)];
    }
    this->corners.resize(static_cast<size_t>(numCorners));
    std::vector<int32_t> cursor(this->offsets.begin(), this->offsets.end() - 1);
    for (int64_t c = 0; c < numCorners; ++c)
    {
      this->corners[static_cast<size_t>(cursor[static_cast<size_t>(conn[c])]++)] = static_cast<int32_t>(c);
    }
  }
};

} // namespace slnormals

#endif
