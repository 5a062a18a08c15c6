#ifndef slVertexNormalsCore_h
#define slVertexNormalsCore_h
/**
 * @file slVertexNormalsCore.h
 * @brief Vertex normals without splitting: weighted face normals summed at
 * each vertex. VTK-free. Internal to ShadeLab::Normals.
 *
 * The polygons are cut into as many contiguous chunks as there are threads;
 * each chunk scatters its corner contributions into its own accumulator, and a
 * parallel pass over the points adds the accumulators and normalises. The
 * result does not depend on scheduling (the sum order is fixed).
 */

#include "slCornerWeights.h"
#include "slFaceNormalsCore.h"
#include "slNormalsParallel.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <type_traits>
#include <vector>

namespace slnormals
{

namespace detail
{
template <typename T>
inline void add(T* acc, int64_t id, const glm::vec<3, T>& v)
{
  acc[3 * id] += v.x;
  acc[3 * id + 1] += v.y;
  acc[3 * id + 2] += v.z;
}

/// Adds the corner contributions of polygons [b, e) into @p acc, at the
/// corners' entries of @p accIds (same layout as the connectivity).
template <Weighting W, typename T, typename Id, typename AccId>
void scatter(const Polygons<Id>& polys, const AccId* accIds, const T* xyz, int64_t b, int64_t e, T* acc)
{
  using V = glm::vec<3, T>;
  for (int64_t f = b; f < e; ++f)
  {
    const int64_t o = polys.begin(f);
    const int64_t n = polys.size(f);
    const Id* ids = polys.connectivity + o;
    const AccId* to = accIds + o;
    if (n == 3)
    {
      const V p0 = point(xyz, ids[0]), p1 = point(xyz, ids[1]), p2 = point(xyz, ids[2]);
      const V nv = glm::cross(p1 - p0, p2 - p0);
      const T len = glm::length(nv);
      if (!(len > T(0)))
      {
        continue;
      }
      if (W == Weighting::Area)
      {
        add(acc, to[0], nv);
        add(acc, to[1], nv);
        add(acc, to[2], nv);
        continue;
      }
      const V u = nv / len;
      if (W == Weighting::Uniform)
      {
        add(acc, to[0], u);
        add(acc, to[1], u);
        add(acc, to[2], u);
        continue;
      }
      if (W == Weighting::Angle)
      {
        // Two angles by acos, the third from the angle sum.
        const V a = p1 - p0, bb = p2 - p1, c = p0 - p2;
        const T la = glm::dot(a, a), lb = glm::dot(bb, bb), lc = glm::dot(c, c);
        const T t0 = fastAcos(-glm::dot(c, a) / std::sqrt(lc * la));
        const T t1 = fastAcos(-glm::dot(a, bb) / std::sqrt(la * lb));
        const T t2 = T(3.14159265358979323846) - t0 - t1;
        add(acc, to[0], u * t0);
        add(acc, to[1], u * t1);
        add(acc, to[2], u * (t2 > T(0) ? t2 : T(0)));
        continue;
      }
      // Max: |e1 x e2| / (|e1|^2 |e2|^2) at every corner; |e1 x e2| = len.
      const V a = p1 - p0, bb = p2 - p1, c = p0 - p2;
      const T la = glm::dot(a, a), lb = glm::dot(bb, bb), lc = glm::dot(c, c);
      add(acc, to[0], u * (len / (lc * la)));
      add(acc, to[1], u * (len / (la * lb)));
      add(acc, to[2], u * (len / (lb * lc)));
      continue;
    }
    if (n < 3)
    {
      continue;
    }
    const V nv = newellVector(polys, xyz, f);
    const T len = glm::length(nv);
    if (!(len > T(0)))
    {
      continue;
    }
    const V u = nv / len;
    for (int64_t i = 0; i < n; ++i)
    {
      const V prev = point(xyz, ids[(i + n - 1) % n]);
      const V next = point(xyz, ids[(i + 1) % n]);
      add(acc, to[i], cornerContribution(W, prev, point(xyz, ids[i]), next, u, len));
    }
  }
}
} // namespace detail

/// Normalised sums of corner contributions, indexed by @p accIds (the
/// connectivity's layout, values in [0, numPoints)), into @p out (3 floats
/// each). Entries no non-degenerate corner reaches get (0, 0, 0).
template <typename T, typename Id, typename AccId>
void accumulateNormals(const Polygons<Id>& polys, const AccId* accIds, const T* xyz, int64_t numPoints,
  Weighting weighting, float* out, const Parallel& parallel)
{
  const int64_t chunks =
    polys.numPolygons < 65536 ? 1 : std::max<int64_t>(1, std::min<int64_t>(parallel.threads, 64));
  // With float points, the first chunk accumulates straight into the output.
  constexpr bool inPlace = std::is_same<T, float>::value;
  std::vector<std::vector<T>> acc(static_cast<size_t>(chunks));
  std::vector<T*> target(static_cast<size_t>(chunks));
  parallel.forRange(0, chunks, 1, [&](int64_t cb, int64_t ce) {
    for (int64_t k = cb; k < ce; ++k)
    {
      T* a;
      if (inPlace && k == 0)
      {
        a = reinterpret_cast<T*>(out);
        std::fill(a, a + 3 * numPoints, T(0));
      }
      else
      {
        acc[static_cast<size_t>(k)].assign(static_cast<size_t>(3 * numPoints), T(0));
        a = acc[static_cast<size_t>(k)].data();
      }
      target[static_cast<size_t>(k)] = a;
      const int64_t b = polys.numPolygons * k / chunks;
      const int64_t e = polys.numPolygons * (k + 1) / chunks;
      switch (weighting)
      {
        case Weighting::Uniform:
          detail::scatter<Weighting::Uniform>(polys, accIds, xyz, b, e, a);
          break;
        case Weighting::Area:
          detail::scatter<Weighting::Area>(polys, accIds, xyz, b, e, a);
          break;
        case Weighting::Angle:
          detail::scatter<Weighting::Angle>(polys, accIds, xyz, b, e, a);
          break;
        case Weighting::Max:
          detail::scatter<Weighting::Max>(polys, accIds, xyz, b, e, a);
          break;
      }
    }
  });
  parallel.forRange(0, numPoints, 16384, [&](int64_t b, int64_t e) {
    for (int64_t v = b; v < e; ++v)
    {
      glm::vec<3, T> s(0);
      for (const T* a : target)
      {
        s += glm::vec<3, T>(a[3 * v], a[3 * v + 1], a[3 * v + 2]);
      }
      const T len = glm::length(s);
      if (len > T(0))
      {
        s /= len;
      }
      out[3 * v] = static_cast<float>(s.x);
      out[3 * v + 1] = static_cast<float>(s.y);
      out[3 * v + 2] = static_cast<float>(s.z);
    }
  });
}

/// Unit vertex normals of points [0, numPoints) into @p out (3 floats each).
/// Points used by no non-degenerate polygon get (0, 0, 0).
template <typename T, typename Id>
void computeVertexNormals(const Polygons<Id>& polys, const T* xyz, int64_t numPoints, Weighting weighting,
  float* out, const Parallel& parallel)
{
  accumulateNormals(polys, polys.connectivity, xyz, numPoints, weighting, out, parallel);
}

} // namespace slnormals

#endif
