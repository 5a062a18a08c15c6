#ifndef slVertexNormalsCore_h
#define slVertexNormalsCore_h
/**
 * @file slVertexNormalsCore.h
 * @brief Vertex normals without splitting: weighted face normals summed at
 * each vertex. VTK-free. Geometry core (ShadeLab::GeometryCore).
 *
 * Triangles are weighed in vectorised blocks (slTriangleBlock.h). The
 * polygons are cut into as many contiguous chunks as there are threads;
 * each chunk scatters its corner contributions into its own accumulator, and a
 * parallel pass over the points adds the accumulators and normalises. The
 * result does not depend on scheduling (the sum order is fixed).
 */

#include "slCornerWeights.h"
#include "slFaceNormalsCore.h"
#include "slNormalsParallel.h"
#include "slTriangleBlock.h"

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
/// corners' entries of @p accIds (same layout as the connectivity). Runs of
/// consecutive triangles go through TriangleBlock; other polygons one by one.
template <Weighting W, typename T, typename Id, typename AccId>
void scatter(const Polygons<Id>& polys, const AccId* accIds, const T* xyz, int64_t b, int64_t e, T* acc)
{
  using V = glm::vec<3, T>;
  TriangleBlock<T> block;
  const auto flush = [&]() {
    block.template weigh<W>();
    block.scatter(accIds, acc);
    block.count = 0;
  };
  for (int64_t f = b; f < e; ++f)
  {
    const int64_t o = polys.begin(f);
    const int64_t n = polys.size(f);
    if (n == 3)
    {
      if (!block.continues(o))
      {
        flush();
      }
      block.add(polys.connectivity, xyz, o);
      if (block.count == TriangleBlock<T>::Capacity)
      {
        flush();
      }
      continue;
    }
    const V nv = newellVector(polys, xyz, f);
    const T len = glm::length(nv);
    if (n < 3 || !(len > T(0)))
    {
      continue;
    }
    const Id* ids = polys.connectivity + o;
    const AccId* to = accIds + o;
    const V u = nv / len;
    for (int64_t i = 0; i < n; ++i)
    {
      const V prev = point(xyz, ids[(i + n - 1) % n]);
      const V next = point(xyz, ids[(i + 1) % n]);
      add(acc, to[i], cornerContribution(W, prev, point(xyz, ids[i]), next, u, len));
    }
  }
  if (block.count > 0)
  {
    flush();
  }
}

/// Where chunk 0 accumulates: straight into the float output when the
/// points are float (saves one accumulator), else nowhere (null).
template <typename T>
inline T* inPlaceAccumulator(float* out)
{
  if constexpr (std::is_same<T, float>::value)
  {
    return out;
  }
  else
  {
    (void)out;
    return nullptr;
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
  std::vector<std::vector<T>> acc(static_cast<size_t>(chunks));
  std::vector<T*> target(static_cast<size_t>(chunks));
  parallel.forRange(0, chunks, 1, [&](int64_t cb, int64_t ce) {
    for (int64_t k = cb; k < ce; ++k)
    {
      T* a = k == 0 ? detail::inPlaceAccumulator<T>(out) : nullptr;
      if (a)
      {
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
