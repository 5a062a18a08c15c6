#ifndef slFeatureSplitCore_h
#define slFeatureSplitCore_h
/**
 * @file slFeatureSplitCore.h
 * @brief Vertex normals with feature-angle splitting. VTK-free. Internal to
 * ShadeLab::Normals.
 *
 * Around each point, the polygons at it are joined into smooth groups: two
 * polygons sharing an edge at the point join when the edge is manifold (no
 * third polygon on it) and the angle between their normals is at most the
 * feature angle. A degenerate polygon joins any neighbour. Each group becomes
 * one output point with its own normal (the weighted sum over the group), so
 * sharp and non-manifold edges stay sharp while smooth edges stay shared.
 *
 * When the polygons are given with welded point ids (@p topology) and their
 * original ids (@p original), an output point is one (original point, group)
 * pair: normals are computed on the welded surface, but points that differed
 * in the input (texture seams) stay apart.
 *
 * Work is parallel over points in two passes (count, then write) that both
 * rebuild the groups, which costs time but no memory per corner.
 */

#include "slCornerWeights.h"
#include "slFaceNormalsCore.h"
#include "slNormalsParallel.h"
#include "slVertexCorners.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <numeric>
#include <utility>
#include <vector>

namespace slnormals
{

/// Where the split result goes; filled in by allocate(numOutputPoints).
struct SplitOutput
{
  float* normals = nullptr; ///< 3 per output point
  int64_t* source = nullptr; ///< input point of each output point
};

namespace detail
{
/// Scratch space of one thread, reused from point to point.
template <typename T>
struct SplitScratch
{
  std::vector<int64_t> face, prev, next, orig;
  std::vector<glm::vec<3, T>> unit; ///< unit polygon normal per corner
  std::vector<T> len;               ///< Newell vector length per corner
  std::vector<int> parent;
  std::vector<std::pair<int64_t, int>> edges;
  std::vector<int> group;       ///< per corner, 0..numGroups-1
  std::vector<int> slot;        ///< per corner, 0..numSlots-1
  std::vector<std::pair<int64_t, int>> slots; ///< (original id, group) per slot
  std::vector<glm::vec<3, T>> sums;

  int find(int i)
  {
    while (this->parent[i] != i)
    {
      this->parent[i] = this->parent[this->parent[i]];
      i = this->parent[i];
    }
    return i;
  }
};

/// Builds the groups and slots of point @p v; returns the number of slots.
template <typename T, typename Id>
int groupCorners(const Polygons<Id>& polys, const Id* original, const T* xyz, const VertexCorners<Id>& vc,
  int64_t v, T cosFeature, bool split, SplitScratch<T>& s)
{
  const int32_t b = vc.offsets[static_cast<size_t>(v)];
  const int k = vc.offsets[static_cast<size_t>(v) + 1] - b;
  s.face.resize(k);
  s.prev.resize(k);
  s.next.resize(k);
  s.orig.resize(k);
  s.unit.resize(k);
  s.len.resize(k);
  s.parent.resize(k);
  s.group.resize(k);
  s.slot.resize(k);
  s.edges.clear();
  for (int i = 0; i < k; ++i)
  {
    const int64_t c = vc.corners[static_cast<size_t>(b + i)];
    const int64_t f = vc.faceOf(c);
    s.face[i] = f;
    s.next[i] = polys.connectivity[c + 1 == polys.end(f) ? polys.begin(f) : c + 1];
    s.prev[i] = polys.connectivity[c == polys.begin(f) ? polys.end(f) - 1 : c - 1];
    s.orig[i] = original ? static_cast<int64_t>(original[c]) : v;
    s.parent[i] = i;
    const glm::vec<3, T> n = newellVector(polys, xyz, f);
    s.len[i] = glm::length(n);
    s.unit[i] = s.len[i] > T(0) ? n / s.len[i] : glm::vec<3, T>(0);
    if (split)
    {
      s.edges.emplace_back(s.next[i], i);
      s.edges.emplace_back(s.prev[i], i);
    }
  }
  if (split)
  {
    std::sort(s.edges.begin(), s.edges.end());
    for (size_t e = 0; e < s.edges.size();)
    {
      size_t end = e + 1;
      while (end < s.edges.size() && s.edges[end].first == s.edges[e].first)
      {
        ++end;
      }
      if (end - e == 2)
      {
        const int i = s.edges[e].second, j = s.edges[e + 1].second;
        const T d = glm::dot(s.unit[i], s.unit[j]);
        const bool degenerate = glm::dot(s.unit[i], s.unit[i]) == T(0) || glm::dot(s.unit[j], s.unit[j]) == T(0);
        if (degenerate || d >= cosFeature)
        {
          s.parent[s.find(i)] = s.find(j);
        }
      }
      e = end;
    }
  }
  // Compact groups in order of first corner, then (original, group) slots.
  int groups = 0;
  std::fill(s.group.begin(), s.group.end(), -1);
  for (int i = 0; i < k; ++i)
  {
    const int r = split ? s.find(i) : 0;
    if (s.group[r] < 0)
    {
      s.group[r] = groups++;
    }
  }
  s.slots.clear();
  for (int i = 0; i < k; ++i)
  {
    const int g = s.group[split ? s.find(i) : 0];
    const std::pair<int64_t, int> key(s.orig[i], g);
    const auto it = std::find(s.slots.begin(), s.slots.end(), key);
    s.slot[i] = static_cast<int>(it - s.slots.begin());
    if (it == s.slots.end())
    {
      s.slots.push_back(key);
    }
  }
  return static_cast<int>(s.slots.size());
}
} // namespace detail

/**
 * Splits points along feature edges and computes their normals.
 * @p topology: polygons on welded ids (size numPoints); @p original: the
 * same polygons' original point ids, or null when not welded; @p vc: the
 * corner table of @p topology. @p allocate(numOutputPoints) returns where to
 * write; @p outConnectivity (same size as the connectivity) receives the
 * output point id of every corner. Returns the number of output points;
 * points used by no polygon are not output.
 */
template <typename T, typename Id, typename OutId, typename Allocate>
int64_t splitVertexNormals(const Polygons<Id>& topology, const Id* original, const T* xyz, int64_t numPoints,
  const VertexCorners<Id>& vc, Weighting weighting, T cosFeature, bool split, OutId* outConnectivity,
  Allocate&& allocate, const Parallel& parallel)
{
  std::vector<int64_t> base(static_cast<size_t>(numPoints + 1), 0);
  parallel.forRange(0, numPoints, 4096, [&](int64_t b, int64_t e) {
    detail::SplitScratch<T> s;
    for (int64_t v = b; v < e; ++v)
    {
      base[static_cast<size_t>(v + 1)] = detail::groupCorners(topology, original, xyz, vc, v, cosFeature, split, s);
    }
  });
  for (int64_t v = 0; v < numPoints; ++v)
  {
    base[static_cast<size_t>(v + 1)] += base[static_cast<size_t>(v)];
  }
  const int64_t total = base[static_cast<size_t>(numPoints)];
  SplitOutput out = allocate(total);
  parallel.forRange(0, numPoints, 4096, [&](int64_t b, int64_t e) {
    detail::SplitScratch<T> s;
    for (int64_t v = b; v < e; ++v)
    {
      detail::groupCorners(topology, original, xyz, vc, v, cosFeature, split, s);
      const int k = static_cast<int>(s.face.size());
      s.sums.assign(static_cast<size_t>(k), glm::vec<3, T>(0));
      const glm::vec<3, T> p = point(xyz, v);
      for (int i = 0; i < k; ++i)
      {
        s.sums[static_cast<size_t>(s.group[split ? s.find(i) : 0])] +=
          cornerContribution(weighting, point(xyz, s.prev[i]), p, point(xyz, s.next[i]), s.unit[i], s.len[i]);
      }
      for (int i = 0; i < k; ++i)
      {
        const int64_t id = base[static_cast<size_t>(v)] + s.slot[i];
        glm::vec<3, T> n = s.sums[static_cast<size_t>(s.group[split ? s.find(i) : 0])];
        const T len = glm::length(n);
        n = len > T(0) ? n / len : glm::vec<3, T>(0);
        out.normals[3 * id] = static_cast<float>(n.x);
        out.normals[3 * id + 1] = static_cast<float>(n.y);
        out.normals[3 * id + 2] = static_cast<float>(n.z);
        out.source[id] = s.orig[i];
        outConnectivity[vc.corners[static_cast<size_t>(vc.offsets[static_cast<size_t>(v)] + i)]] =
          static_cast<OutId>(id);
      }
    }
  });
  return total;
}

} // namespace slnormals

#endif
