#ifndef slTangentFramesCore_h
#define slTangentFramesCore_h
/**
 * @file slTangentFramesCore.h
 * @brief Per-vertex tangent frames from texture coordinates, after
 * MikkTSpace. VTK-free. Geometry core (ShadeLab::GeometryCore).
 *
 * For each polygon (fan-triangulated from its first vertex) the tangent is
 * the direction of increasing u on the surface,
 * T = (e1 dv2 − e2 dv1) / (du1 dv2 − du2 dv1), and its orientation sign is the
 * sign of its signed UV area (+1 when the UV map keeps orientation, −1 when
 * it is mirrored). As MikkTSpace does, at each corner T is projected onto
 * the vertex's tangent plane, normalised, and weighted by the corner angle;
 * corners of opposite sign are summed apart. A vertex whose corners have
 * both signs (a mirror seam) gets two frames; the caller duplicates it.
 * Triangles with zero UV area contribute nothing; a vertex with no
 * contribution gets a unit tangent orthogonal to its normal, chosen from the
 * axis least aligned with it, and w = +1.
 */

#include "slCornerWeights.h"
#include "slNormalsParallel.h"

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

namespace slnormals
{

/// Frames of one vertex: index 0 for w = +1, 1 for w = −1.
struct TangentSums
{
  std::vector<glm::dvec3> sum[2];
  std::vector<char> used[2];
};

/// Unit vector orthogonal to unit @p n, from the axis least aligned with it.
inline glm::dvec3 anyTangent(const glm::dvec3& n)
{
  const glm::dvec3 a = std::fabs(n.x) <= std::fabs(n.y) && std::fabs(n.x) <= std::fabs(n.z)
    ? glm::dvec3(1, 0, 0)
    : (std::fabs(n.y) <= std::fabs(n.z) ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1));
  return glm::normalize(a - n * glm::dot(n, a));
}

/// The tangent and orientation sign (+1, −1, or 0 when the UV area is zero)
/// of the triangle (p0, p1, p2) with texture coordinates (t0, t1, t2).
inline int triangleTangent(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec2& t0,
  const glm::dvec2& t1, const glm::dvec2& t2, glm::dvec3& tangent)
{
  const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0;
  const glm::dvec2 d1 = t1 - t0, d2 = t2 - t0;
  const double r = d1.x * d2.y - d2.x * d1.y;
  if (!(std::fabs(r) > 0.0) || !std::isfinite(r))
  {
    return 0;
  }
  tangent = (e1 * d2.y - e2 * d1.y) / r;
  return r > 0 ? 1 : -1;
}

/// Accumulates the frames of every vertex. @p normal(v) gives the unit
/// normal, @p pos(v) the position, @p uv(v) the texture coordinates;
/// @p sign receives the orientation sign of every connectivity position.
template <typename Id, typename Pos, typename UV, typename Normal>
void accumulateTangents(const Polygons<Id>& polys, int64_t numPoints, Pos&& pos, UV&& uv, Normal&& normal,
  TangentSums& sums, std::vector<signed char>& sign)
{
  for (int s = 0; s < 2; ++s)
  {
    sums.sum[s].assign(static_cast<size_t>(numPoints), glm::dvec3(0));
    sums.used[s].assign(static_cast<size_t>(numPoints), 0);
  }
  const int64_t numCorners = polys.numPolygons ? polys.end(polys.numPolygons - 1) : 0;
  sign.assign(static_cast<size_t>(numCorners), 0);
  for (int64_t f = 0; f < polys.numPolygons; ++f)
  {
    const int64_t b = polys.begin(f), n = polys.size(f);
    for (int64_t k = 1; k + 1 < n; ++k)
    {
      const int64_t c[3] = { b, b + k, b + k + 1 };
      const int64_t v[3] = { polys.connectivity[c[0]], polys.connectivity[c[1]], polys.connectivity[c[2]] };
      glm::dvec3 t;
      const int s = triangleTangent(pos(v[0]), pos(v[1]), pos(v[2]), uv(v[0]), uv(v[1]), uv(v[2]), t);
      if (s == 0)
      {
        continue;
      }
      const int slot = s > 0 ? 0 : 1;
      // Twice the triangle's area: the cross length all three corners share.
      const double crossLength = glm::length(glm::cross(pos(v[1]) - pos(v[0]), pos(v[2]) - pos(v[0])));
      for (int i = 0; i < 3; ++i)
      {
        sign[static_cast<size_t>(c[i])] = static_cast<signed char>(s);
        const glm::dvec3 nv = normal(v[i]);
        glm::dvec3 tp = t - nv * glm::dot(nv, t);
        const double len = glm::length(tp);
        if (!(len > 0.0))
        {
          continue;
        }
        const glm::dvec3 e1 = pos(v[(i + 1) % 3]) - pos(v[i]), e2 = pos(v[(i + 2) % 3]) - pos(v[i]);
        const double angle = cornerAngle(crossLength, glm::dot(e1, e2));
        sums.sum[slot][static_cast<size_t>(v[i])] += tp / len * angle;
        sums.used[slot][static_cast<size_t>(v[i])] = 1;
      }
    }
  }
}

/// The final xyz of a frame: the sum orthogonalised to @p n and normalised,
/// or anyTangent(n) when it vanishes.
inline glm::dvec3 finishTangent(const glm::dvec3& sum, const glm::dvec3& n)
{
  const glm::dvec3 t = sum - n * glm::dot(n, sum);
  const double len = glm::length(t);
  return len > 1e-300 ? t / len : anyTangent(n);
}

} // namespace slnormals

#endif
