#ifndef slFaceNormalsCore_h
#define slFaceNormalsCore_h
/**
 * @file slFaceNormalsCore.h
 * @brief Polygon normals by Newell's method. VTK-free. Geometry
 * core (ShadeLab::GeometryCore).
 *
 * For a triangle the Newell vector equals (P1−P0)×(P2−P0); for a polygon with
 * more than three vertices it is Σ (Pi − C) × (Pi+1 − C) over its edges (C any
 * point: the first vertex here), which stays exact for non-convex planar
 * polygons and is a least-squares normal for non-planar ones. Its length is
 * twice the polygon's area.
 */

#include "slNormalsParallel.h"

#include <glm/glm.hpp>

namespace slnormals
{

template <typename T>
inline glm::vec<3, T> point(const T* xyz, int64_t id)
{
  return glm::vec<3, T>(xyz[3 * id], xyz[3 * id + 1], xyz[3 * id + 2]);
}

/// The Newell vector of polygon @p f (zero for fewer than three vertices).
template <typename T, typename Id>
inline glm::vec<3, T> newellVector(const Polygons<Id>& polys, const T* xyz, int64_t f)
{
  const int64_t b = polys.begin(f);
  const int64_t n = polys.size(f);
  if (n < 3)
  {
    return glm::vec<3, T>(0);
  }
  const glm::vec<3, T> p0 = point(xyz, polys.connectivity[b]);
  if (n == 3)
  {
    return glm::cross(point(xyz, polys.connectivity[b + 1]) - p0, point(xyz, polys.connectivity[b + 2]) - p0);
  }
  glm::vec<3, T> sum(0);
  glm::vec<3, T> prev = point(xyz, polys.connectivity[b + 1]) - p0;
  for (int64_t i = 2; i < n; ++i)
  {
    const glm::vec<3, T> cur = point(xyz, polys.connectivity[b + i]) - p0;
    sum += glm::cross(prev, cur);
    prev = cur;
  }
  return sum;
}

/// Unit normals of every polygon into @p out (3 floats each); degenerate
/// polygons get (0, 0, 0).
template <typename T, typename Id>
void computeUnitFaceNormals(const Polygons<Id>& polys, const T* xyz, float* out, const Parallel& parallel)
{
  parallel.forRange(0, polys.numPolygons, 4096, [&](int64_t b, int64_t e) {
    for (int64_t f = b; f < e; ++f)
    {
      const glm::vec<3, T> n = newellVector(polys, xyz, f);
      const T len = glm::length(n);
      const glm::vec<3, T> u = len > T(0) ? n / len : glm::vec<3, T>(0);
      out[3 * f] = static_cast<float>(u.x);
      out[3 * f + 1] = static_cast<float>(u.y);
      out[3 * f + 2] = static_cast<float>(u.z);
    }
  });
}

} // namespace slnormals

#endif
