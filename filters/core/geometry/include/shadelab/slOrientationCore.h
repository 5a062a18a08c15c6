#ifndef slOrientationCore_h
#define slOrientationCore_h
/**
 * @file slOrientationCore.h
 * @brief Consistent polygon orientation across shared edges, and outward
 * orientation of closed surfaces. VTK-free. Geometry core (ShadeLab::GeometryCore).
 *
 * Two polygons sharing a manifold edge (exactly two polygons on it) are
 * consistent when they traverse it in opposite directions. A parallel check
 * looks for an inconsistent edge first; only if one exists does a serial
 * breadth-first walk over manifold edges reverse polygons, seeded by the
 * first polygon of each connected piece, which keeps its orientation.
 * Non-manifold edges (three or more polygons) and boundary edges do not
 * propagate orientation.
 *
 * Outward: a piece is closed when none of its edges is a boundary edge. Its
 * signed volume is Σ P0 · N / 6 over its polygons (N the Newell vector); a
 * closed piece with negative volume is reversed as a whole. Open pieces keep
 * the orientation of their seed.
 */

#include "slFaceNormalsCore.h"
#include "slNormalsParallel.h"
#include "slVertexCorners.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <deque>
#include <utility>
#include <vector>

namespace slnormals
{

namespace detail
{
/// Position of point @p a in polygon @p f, or -1.
template <typename Id>
inline int64_t findInPolygon(const Polygons<Id>& polys, int64_t f, int64_t a)
{
  for (int64_t c = polys.begin(f); c < polys.end(f); ++c)
  {
    if (static_cast<int64_t>(polys.connectivity[c]) == a)
    {
      return c;
    }
  }
  return -1;
}

template <typename Id>
inline int64_t nextPos(const Polygons<Id>& polys, int64_t f, int64_t c)
{
  return c + 1 == polys.end(f) ? polys.begin(f) : c + 1;
}

template <typename Id>
inline int64_t prevPos(const Polygons<Id>& polys, int64_t f, int64_t c)
{
  return c == polys.begin(f) ? polys.end(f) - 1 : c - 1;
}

/// The polygons other than @p f on edge (a, b): calls visit(g, sameDirection).
template <typename Id, typename Visit>
inline void forEdgeNeighbours(const Polygons<Id>& polys, const VertexCorners<Id>& vc, int64_t f, int64_t a,
  int64_t b, Visit&& visit)
{
  for (int32_t i = vc.offsets[static_cast<size_t>(a)]; i < vc.offsets[static_cast<size_t>(a) + 1]; ++i)
  {
    const int64_t corner = vc.corners[static_cast<size_t>(i)];
    const int64_t g = vc.faceOf(corner);
    if (g == f)
    {
      continue;
    }
    // The table's position holds a unless its polygon has been reversed since.
    const int64_t c = static_cast<int64_t>(polys.connectivity[corner]) == a ? corner : findInPolygon(polys, g, a);
    if (c < 0)
    {
      continue;
    }
    if (static_cast<int64_t>(polys.connectivity[nextPos(polys, g, c)]) == b)
    {
      visit(g, true);
    }
    else if (static_cast<int64_t>(polys.connectivity[prevPos(polys, g, c)]) == b)
    {
      visit(g, false);
    }
  }
}

template <typename Id>
inline void reversePolygon(Polygons<Id>& polys, int64_t f)
{
  std::reverse(polys.connectivity + polys.begin(f), polys.connectivity + polys.end(f));
}

/// True if two of the @p n values repeat: at a point, two corners whose
/// next points repeat traverse that edge in the same direction. n is a
/// point's valence, so comparing all pairs is cheaper than any set.
inline bool hasRepeat(const int64_t* values, int n)
{
  for (int i = 1; i < n; ++i)
  {
    for (int j = 0; j < i; ++j)
    {
      if (values[i] == values[j])
      {
        return true;
      }
    }
  }
  return false;
}
} // namespace detail

/// True if two polygons traverse some shared edge in the same direction:
/// at some point v, two corners continue to the same next point.
template <typename Id>
bool hasInconsistentEdge(const Polygons<Id>& polys, const VertexCorners<Id>& vc, const Parallel& parallel)
{
  const int64_t numPoints = static_cast<int64_t>(vc.offsets.size()) - 1;
  std::atomic<bool> found{ false };
  parallel.forRange(0, numPoints, 8192, [&](int64_t b, int64_t e) {
    std::vector<int64_t> next;
    for (int64_t v = b; v < e && !found.load(std::memory_order_relaxed); ++v)
    {
      const int32_t first = vc.offsets[static_cast<size_t>(v)];
      const int k = vc.offsets[static_cast<size_t>(v) + 1] - first;
      next.resize(static_cast<size_t>(k));
      for (int i = 0; i < k; ++i)
      {
        next[static_cast<size_t>(i)] = polys.connectivity[vc.around(polys, vc.corners[static_cast<size_t>(first + i)]).next];
      }
      if (detail::hasRepeat(next.data(), k))
      {
        found = true;
      }
    }
  });
  return found;
}

namespace detail
{
/// The signed volume Σ P0 · N / 6 of each of @p pieces pieces (@p piece
/// gives each polygon's), times a power of two of the piece's own, positive:
/// only the sign is used. The points of a piece are scaled by 2^-e, e the
/// exponent of its largest coordinate, and its Newell vectors computed from
/// them in double: the terms grow as the cube of the size, and unscaled they
/// overflowed (or underflowed to 0) for surfaces beyond about 10^±100 in
/// double and, with the Newell vector in float, beyond about 10^19 in float.
/// Scaling by a power of two changes no digit of a coordinate.
template <typename T, typename Id>
std::vector<double> scaledVolumes(
  const Polygons<Id>& polys, const T* xyz, const std::vector<int32_t>& piece, int32_t pieces)
{
  std::vector<double> largest(static_cast<size_t>(pieces), 0.0);
  for (int64_t f = 0; f < polys.numPolygons; ++f)
  {
    double& l = largest[static_cast<size_t>(piece[static_cast<size_t>(f)])];
    for (int64_t c = polys.begin(f); c < polys.end(f); ++c)
    {
      const T* p = xyz + 3 * static_cast<int64_t>(polys.connectivity[c]);
      l = std::max({ l, std::abs(static_cast<double>(p[0])), std::abs(static_cast<double>(p[1])),
        std::abs(static_cast<double>(p[2])) });
    }
  }
  std::vector<double> scale(static_cast<size_t>(pieces), 1.0);
  for (size_t k = 0; k < scale.size(); ++k)
  {
    // A largest coordinate below the normal doubles (2^-1022) is scaled by
    // 2^1000 at most, which 2^1022 would overflow.
    scale[k] = largest[k] > 0.0 ? std::ldexp(1.0, -std::max(std::ilogb(largest[k]), -1000)) : 1.0;
  }
  std::vector<double> volume(static_cast<size_t>(pieces), 0.0);
  for (int64_t f = 0; f < polys.numPolygons; ++f)
  {
    const int64_t n = polys.size(f);
    if (n < 3)
    {
      continue;
    }
    const size_t id = static_cast<size_t>(piece[static_cast<size_t>(f)]);
    const double s = scale[id];
    const auto scaled = [&](int64_t c) { return glm::dvec3(point(xyz, polys.connectivity[c])) * s; };
    const int64_t b = polys.begin(f);
    const glm::dvec3 p0 = scaled(b);
    glm::dvec3 newell(0.0);
    glm::dvec3 prev = scaled(b + 1) - p0;
    for (int64_t i = 2; i < n; ++i)
    {
      const glm::dvec3 cur = scaled(b + i) - p0;
      newell += glm::cross(prev, cur);
      prev = cur;
    }
    volume[id] += glm::dot(p0, newell);
  }
  return volume;
}
} // namespace detail

/// Reverses polygons so that neighbours agree, and closed pieces face
/// outward if @p outward. Returns the number of polygons reversed;
/// @p flippedOut (if given) gets 1 for each. @p vc must describe @p polys.
/// A full pass over the mesh: call it when an edge is known to be used the
/// same way by two polygons (hasInconsistentEdge, or the split path's own
/// check) or when @p outward is wanted, not to find out.
template <typename T, typename Id>
int64_t orientPolygons(
  Polygons<Id>& polys, const T* xyz, const VertexCorners<Id>& vc, bool outward, std::vector<char>* flippedOut = nullptr)
{
  std::vector<int32_t> piece(static_cast<size_t>(polys.numPolygons), -1);
  std::vector<char> flipped(static_cast<size_t>(polys.numPolygons), 0);
  std::vector<char> closed;
  std::deque<int64_t> queue;
  int32_t pieces = 0;
  for (int64_t seed = 0; seed < polys.numPolygons; ++seed)
  {
    if (piece[static_cast<size_t>(seed)] >= 0)
    {
      continue;
    }
    const int32_t id = pieces++;
    closed.push_back(1);
    piece[static_cast<size_t>(seed)] = id;
    queue.push_back(seed);
    while (!queue.empty())
    {
      const int64_t f = queue.front();
      queue.pop_front();
      for (int64_t c = polys.begin(f); c < polys.end(f); ++c)
      {
        const int64_t a = polys.connectivity[c];
        const int64_t b = polys.connectivity[detail::nextPos(polys, f, c)];
        int64_t count = 0, neighbour = -1;
        bool same = false;
        detail::forEdgeNeighbours(polys, vc, f, a, b, [&](int64_t g, bool s) {
          ++count;
          neighbour = g;
          same = s;
        });
        if (count == 0)
        {
          closed[static_cast<size_t>(id)] = 0;
        }
        if (count != 1 || piece[static_cast<size_t>(neighbour)] >= 0)
        {
          continue;
        }
        if (same)
        {
          detail::reversePolygon(polys, neighbour);
          flipped[static_cast<size_t>(neighbour)] ^= 1;
        }
        piece[static_cast<size_t>(neighbour)] = id;
        queue.push_back(neighbour);
      }
    }
  }
  if (outward)
  {
    const std::vector<double> volume = detail::scaledVolumes(polys, xyz, piece, pieces);
    for (int64_t f = 0; f < polys.numPolygons; ++f)
    {
      const size_t id = static_cast<size_t>(piece[static_cast<size_t>(f)]);
      if (closed[id] && volume[id] < 0.0)
      {
        detail::reversePolygon(polys, f);
        flipped[static_cast<size_t>(f)] ^= 1;
      }
    }
  }
  int64_t total = 0;
  for (char c : flipped)
  {
    total += c;
  }
  if (flippedOut)
  {
    *flippedOut = std::move(flipped);
  }
  return total;
}

} // namespace slnormals

#endif
