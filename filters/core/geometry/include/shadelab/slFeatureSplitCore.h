#ifndef slFeatureSplitCore_h
#define slFeatureSplitCore_h
/**
 * @file slFeatureSplitCore.h
 * @brief Vertex normals with feature-angle splitting. VTK-free. Geometry
 * core (ShadeLab::GeometryCore).
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
 * Work is parallel: unit polygon normals; a pass over points that builds
 * the groups (keeping each corner's group, 16 bits; a point that is one
 * closed fan gets its groups without the general grouping work, see
 * closedFanGroups); then, without welding,
 * each corner's output point and a polygon-centric weighted sum as in
 * slVertexNormalsCore.h; with welding, a second pass over points.
 */

#include "shadelab/Error.h"
#include "slCornerWeights.h"
#include "slFaceNormalsCore.h"
#include "slNormalsParallel.h"
#include "slOrientationCore.h"
#include "slVertexCorners.h"
#include "slVertexNormalsCore.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <atomic>
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
  int k = 0; ///< corners of the point: the per-corner vectors hold k or more entries, the first k its
  std::vector<int64_t> prev, next, orig; ///< per corner (orig only with welding)
  std::vector<glm::vec<3, T>> normal;    ///< unit normal of each corner's polygon
  std::vector<int> parent;
  std::vector<std::pair<int64_t, int>> ends; ///< (other point, corner) per edge end, by point
  std::vector<std::pair<int, int>> edges;    ///< corners joined by a manifold edge (degenerate polygons only)
  std::vector<int> group; ///< per corner, 0..numGroups-1
  std::vector<int> slot;  ///< per corner, 0..numSlots-1 (welding only)
  std::vector<std::pair<int64_t, int>> slots; ///< (original id, group) per slot
  std::vector<glm::vec<3, T>> sums;
  bool fan = false; ///< the last point was one closed fan (consistent by construction)

  /// Room for a point of @p corners corners. The per-corner vectors only
  /// grow: five resizes at every point took a fifth of the grouping's
  /// instructions.
  void resize(int corners)
  {
    this->k = corners;
    const size_t n = static_cast<size_t>(corners);
    if (this->prev.size() < n)
    {
      this->prev.resize(n);
      this->next.resize(n);
      this->orig.resize(n);
      this->normal.resize(n);
      this->group.resize(n);
    }
  }

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

template <typename T>
inline glm::vec<3, T> unitOf(const glm::vec<3, T>& n, T& len)
{
  len = glm::length(n);
  return len > T(0) ? n / len : glm::vec<3, T>(0);
}

/// True if two polygons with unit normals @p ni, @p nj (zero if degenerate)
/// across a manifold edge join one smooth group: a degenerate polygon joins
/// any neighbour, others when their normals are at most the feature angle
/// apart. (A point with degenerate corners among others is grouped by
/// buildGroups() without it: joined to everything, a degenerate polygon
/// would join two faces across the sharp edge it lies between.)
template <typename T>
inline bool smoothAcross(const glm::vec<3, T>& ni, const glm::vec<3, T>& nj, T cosFeature)
{
  // The usual answer (a smooth edge) first.
  return glm::dot(ni, nj) >= cosFeature || glm::dot(ni, ni) == T(0) || glm::dot(nj, nj) == T(0);
}

/// Fans of at most this many corners (nearly all) find their walk's steps
/// with a small hash table (fanSteps); larger ones scan for each step.
constexpr int kHashedFan = 32;

/// The fan walk's step of every corner at once: @p to[i] is the first corner
/// j whose previous point is corner i's next point (prev[j] == next[i]);
/// false if some corner has no such j. @p k is at most kHashedFan: the
/// previous points go into a 64-slot open-addressing table (Fibonacci
/// hashing), and the k steps cost about 2k probes instead of k² compares.
inline bool fanSteps(const int64_t* prev, const int64_t* next, int k, int* to)
{
  uint8_t slot[64] = {}; // a corner + 1; 0 is empty
  auto home = [](int64_t id) {
    return static_cast<unsigned>((static_cast<uint64_t>(id) * 0x9E3779B97F4A7C15ull) >> 58);
  };
  for (int j = 0; j < k; ++j)
  {
    unsigned h = home(prev[j]);
    while (slot[h])
    {
      h = (h + 1) & 63;
    }
    slot[h] = static_cast<uint8_t>(j + 1);
  }
  for (int i = 0; i < k; ++i)
  {
    unsigned h = home(next[i]);
    for (; slot[h] && prev[slot[h] - 1] != next[i]; h = (h + 1) & 63)
    {
    }
    if (!slot[h])
    {
      return false;
    }
    to[i] = slot[h] - 1;
  }
  return true;
}

/// True if the k (more than kHashedFan) corners in @p s form one closed fan
/// with only smooth edges, walked from corner 0 (see closedFanGroups):
/// each step scans the corners for the one whose previous point is the
/// current corner's next point, and the walk stops at a sharp edge.
template <typename T>
bool smoothClosedFanScanned(const SplitScratch<T>& s, int k, T cosFeature)
{
  int i = 0;
  for (int step = 1; step <= k; ++step)
  {
    // Counted without branches: which prev matches is unpredictable.
    const int64_t w = s.next[static_cast<size_t>(i)];
    int j = -1, matches = 0;
    for (int m = 0; m < k; ++m)
    {
      const bool match = s.prev[static_cast<size_t>(m)] == w;
      matches += match;
      j = match ? m : j;
    }
    if (matches != 1 || !smoothAcross(s.normal[static_cast<size_t>(i)], s.normal[static_cast<size_t>(j)], cosFeature))
    {
      return false;
    }
    if (j == 0)
    {
      return step == k;
    }
    i = j;
  }
  return false;
}

/// The groups of a point whose k corners in @p s form one closed fan, into
/// s.group (numbered in order of first corner), and their number; 0 if the
/// corners are not one closed fan. That is most points of a closed surface,
/// also on its creases, and it is decided by walking the fan once instead
/// of sorting edge ends.
///
/// Each corner i steps to the first corner j whose previous point is its
/// next point (prev[j] == next[i]; fanSteps). If the walk from corner 0
/// comes back to it after exactly k steps, the steps are a k-cycle, so the
/// k next points are distinct, and so are the k previous points: each edge
/// end w at the point is one corner's next and another corner's previous
/// point. Every edge at the point is then manifold and joins the two
/// corners i, j the general pass would join, and the groups are the runs
/// of the cycle between its sharp edges (one group for none or one sharp
/// edge), as the general pass's union would make them. Boundaries,
/// non-manifold edges, bowtie points (two fans) and polygons running the
/// wrong way all fail the walk (a corner without a step, or a return to
/// corner 0 too soon or never) and take the general pass.
///
/// Fans of more than kHashedFan corners are left to the general pass
/// unless they are one smooth closed fan (smoothClosedFanScanned).
template <typename T>
int closedFanGroups(SplitScratch<T>& s, int k, T cosFeature)
{
  if (k > kHashedFan)
  {
    if (!smoothClosedFanScanned(s, k, cosFeature))
    {
      return 0;
    }
    std::fill(s.group.begin(), s.group.begin() + k, 0);
    return 1;
  }
  int to[kHashedFan];
  if (!fanSteps(s.prev.data(), s.next.data(), k, to))
  {
    return 0;
  }
  int step = 1;
  for (int i = to[0]; i != 0 && step <= k; i = to[i])
  {
    ++step;
  }
  if (step != k)
  {
    return 0;
  }
  // Each step's edge, smooth or sharp, tested apart from the walk: along
  // it, each test waited for the step before.
  static_assert(kHashedFan <= 32, "one bit a corner");
  uint32_t sharp = 0;
  for (int i = 0; i < k; ++i)
  {
    sharp |= static_cast<uint32_t>(
               !smoothAcross(s.normal[static_cast<size_t>(i)], s.normal[static_cast<size_t>(to[i])], cosFeature))
      << i;
  }
  if ((sharp & (sharp - 1)) == 0)
  {
    std::fill(s.group.begin(), s.group.begin() + k, 0);
    return 1;
  }
  // Runs once around the cycle from the corner a sharp edge leads to, then
  // renumbered in order of first corner.
  int sharpFrom = 0;
  while (!((sharp >> sharpFrom) & 1))
  {
    ++sharpFrom;
  }
  int run = 0;
  for (int i = to[sharpFrom], n = 0; n < k; ++n, i = to[i])
  {
    s.group[static_cast<size_t>(i)] = run;
    run += (sharp >> i) & 1;
  }
  int number[kHashedFan];
  std::fill(number, number + run, -1);
  int groups = 0;
  for (int i = 0; i < k; ++i)
  {
    int& g = number[s.group[static_cast<size_t>(i)]];
    if (g < 0)
    {
      g = groups++;
    }
    s.group[static_cast<size_t>(i)] = g;
  }
  return groups;
}

/// The union of buildGroups() at a point where degenerate polygons (zero
/// normal) meet others, over its manifold edges s.edges: first the faces
/// across smooth edges, then each degenerate corner with a neighbour that
/// already has a face (repeated, so that a run of degenerate corners joins
/// the face at its start), and last the degenerate corners no face reaches
/// with each other. A degenerate polygon then never joins two faces across
/// the sharp edge it lies on, as a zero-area triangle filling a crack along
/// a cube's edge did, and still has a face's normal where it touches one.
template <typename T>
void joinDegenerateCorners(SplitScratch<T>& s, T cosFeature)
{
  const auto isDegenerate = [&](int i) { return glm::dot(s.normal[i], s.normal[i]) == T(0); };
  for (const std::pair<int, int>& e : s.edges)
  {
    if (!isDegenerate(e.first) && !isDegenerate(e.second) &&
      glm::dot(s.normal[e.first], s.normal[e.second]) >= cosFeature)
    {
      s.parent[s.find(e.first)] = s.find(e.second);
    }
  }
  // Whether each root's group holds a face: only such groups take corners.
  std::vector<char> hasFace(static_cast<size_t>(s.k), 0);
  for (int i = 0; i < s.k; ++i)
  {
    hasFace[static_cast<size_t>(s.find(i))] |= !isDegenerate(i);
  }
  for (bool joined = true; joined;)
  {
    joined = false;
    for (const std::pair<int, int>& e : s.edges)
    {
      const int a = s.find(e.first), b = s.find(e.second);
      if (a != b && hasFace[static_cast<size_t>(a)] != hasFace[static_cast<size_t>(b)])
      {
        // The faceless side joins the face's group.
        const int face = hasFace[static_cast<size_t>(a)] ? a : b;
        s.parent[a == face ? b : a] = face;
        joined = true;
      }
    }
  }
  for (const std::pair<int, int>& e : s.edges)
  {
    const int a = s.find(e.first), b = s.find(e.second);
    if (a != b && !hasFace[static_cast<size_t>(a)] && !hasFace[static_cast<size_t>(b)])
    {
      s.parent[a] = b;
    }
  }
}

/// Builds the groups of point @p v from the polygons' unit normals @p unit
/// (3 per polygon, zero if degenerate) into s.group (per corner,
/// 0..groups-1, in order of first corner) and returns the number of groups.
/// s.fan tells whether the point was one closed fan (closedFanGroups).
template <typename T, typename Id>
int buildGroups(const Polygons<Id>& polys, const Id* original, const T* unit, const VertexCorners<Id>& vc,
  int64_t v, T cosFeature, SplitScratch<T>& s)
{
  const int32_t b = vc.offsets[static_cast<size_t>(v)];
  const int k = vc.offsets[static_cast<size_t>(v) + 1] - b;
  s.resize(k);
  int degenerate = 0;
  for (int i = 0; i < k; ++i)
  {
    const int64_t c = vc.corners[static_cast<size_t>(b + i)];
    const typename VertexCorners<Id>::Around a = vc.around(polys, c);
    s.next[i] = polys.connectivity[a.next];
    s.prev[i] = polys.connectivity[a.prev];
    s.normal[i] = glm::vec<3, T>(unit[3 * a.face], unit[3 * a.face + 1], unit[3 * a.face + 2]);
    degenerate += glm::dot(s.normal[i], s.normal[i]) == T(0);
  }
  // Degenerate corners among others: the faces are grouped without them,
  // then each joins a neighbour's group (degenerateAwareGroups).
  const bool mixed = degenerate > 0 && degenerate < k;
  if (original)
  {
    for (int i = 0; i < k; ++i)
    {
      s.orig[i] = static_cast<int64_t>(original[vc.corners[static_cast<size_t>(b + i)]]);
    }
  }
  const int fanGroups = k > 0 && !mixed ? closedFanGroups(s, k, cosFeature) : 0;
  s.fan = fanGroups > 0;
  if (s.fan)
  {
    return fanGroups;
  }
  s.parent.resize(k);
  std::iota(s.parent.begin(), s.parent.end(), 0);
  // Join corners i, j across each edge (v, w) that exactly these two share.
  // The 2k (w, corner) ends of the edges at v, sorted by w (insertion sort:
  // k is small), put each edge's corners side by side, which costs far less
  // than comparing every corner's edges with every other corner's.
  s.ends.resize(static_cast<size_t>(2 * k));
  for (int e = 0; e < 2 * k; ++e)
  {
    std::pair<int64_t, int> end(e % 2 ? s.prev[e / 2] : s.next[e / 2], e / 2);
    int at = e;
    for (; at > 0 && s.ends[static_cast<size_t>(at - 1)].first > end.first; --at)
    {
      s.ends[static_cast<size_t>(at)] = s.ends[static_cast<size_t>(at - 1)];
    }
    s.ends[static_cast<size_t>(at)] = end;
  }
  s.edges.clear();
  for (int r = 0; r < 2 * k;)
  {
    const int64_t w = s.ends[static_cast<size_t>(r)].first;
    const int i = s.ends[static_cast<size_t>(r)].second;
    int other = -1;
    bool manifold = true; // exactly two corners on the edge
    for (; r < 2 * k && s.ends[static_cast<size_t>(r)].first == w; ++r)
    {
      const int j = s.ends[static_cast<size_t>(r)].second;
      if (j != i && j != other)
      {
        manifold = manifold && other < 0;
        other = j;
      }
    }
    if (!manifold || other < 0)
    {
      continue; // non-manifold or boundary edge
    }
    if (mixed)
    {
      s.edges.emplace_back(i, other);
      continue;
    }
    if (smoothAcross(s.normal[i], s.normal[other], cosFeature))
    {
      s.parent[s.find(i)] = s.find(other);
    }
  }
  if (mixed)
  {
    joinDegenerateCorners(s, cosFeature);
  }
  // Number the groups in order of first corner.
  int groups = 0;
  s.slot.assign(k, -1); // group number of each root
  for (int i = 0; i < k; ++i)
  {
    const int r = s.find(i);
    if (s.slot[r] < 0)
    {
      s.slot[r] = groups++;
    }
    s.group[i] = s.slot[r];
  }
  return groups;
}

/// Builds the groups (see buildGroups) and the slots of point @p v and
/// returns the number of slots. A slot is one output point: a group
/// without welding (s.slot is then not filled: use s.group), an
/// (original id, group) pair with welding (s.slot per corner).
template <typename T, typename Id>
int groupCorners(const Polygons<Id>& polys, const Id* original, const T* unit, const VertexCorners<Id>& vc,
  int64_t v, T cosFeature, SplitScratch<T>& s)
{
  const int groups = buildGroups(polys, original, unit, vc, v, cosFeature, s);
  if (!original)
  {
    return groups;
  }
  const int k = s.k;
  s.slot.resize(k);
  s.slots.clear();
  for (int i = 0; i < k; ++i)
  {
    const std::pair<int64_t, int> key(s.orig[i], s.group[i]);
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
 * corner table of @p topology, emptied when the split no longer needs it
 * (without welding, before the normals are summed: the sums' scratch can
 * take its memory). @p allocate(numOutputPoints) returns where to
 * write; @p outConnectivity (same size as the connectivity) receives the
 * output point id of every corner. Returns the number of output points;
 * points used by no polygon are not output.
 *
 * @p inconsistent, when given, asks the pass that builds the groups to look
 * for polygons running the same way along an edge (hasInconsistentEdge() of
 * slOrientationCore.h, at no extra pass over the corners: a closed fan is
 * consistent by construction). If there is one, *@p inconsistent is set,
 * nothing is allocated or written and -1 is returned: orient the polygons
 * and call again.
 *
 * Memory besides the output: the polygons' unit normals (3 T each), one
 * 16-bit group number per corner (without welding), the output points
 * before each point's (32-bit: fewer than the corners), and the
 * accumulators of slVertexNormalsCore.h.
 */
template <typename T, typename Id, typename OutId, typename Allocate>
int64_t splitVertexNormals(const Polygons<Id>& topology, const Id* original, const T* xyz, int64_t numPoints,
  VertexCorners<Id>& vc, Weighting weighting, T cosFeature, OutId* outConnectivity, Allocate&& allocate,
  const Parallel& parallel, bool* inconsistent = nullptr)
{
  using V = glm::vec<3, T>;
  // Scratch arrays below are filled completely by parallel passes: no zero-fill.
  ScratchArray<T> unit(parallel, static_cast<size_t>(3 * topology.numPolygons));
  parallel.forRange(0, topology.numPolygons, 8192, [&](int64_t b, int64_t e) {
    for (int64_t f = b; f < e; ++f)
    {
      T len;
      const V u = detail::unitOf(newellVector(topology, xyz, f), len);
      unit[3 * f] = u.x;
      unit[3 * f + 1] = u.y;
      unit[3 * f + 2] = u.z;
    }
  });
  constexpr uint16_t recompute = 0xFFFF;
  ScratchArray<uint16_t> stored(parallel, original ? 0 : vc.corners.size());
  const ScratchArray<int32_t> base(parallel, static_cast<size_t>(numPoints + 1));
  base[0] = 0;
  std::atomic<bool> overflow{ false }, wrongWay{ false };
  parallel.forRange(0, numPoints, 4096, [&](int64_t b, int64_t e) {
    detail::SplitScratch<T> s;
    // Flags are stored once per range: a shared flag written per point bounces between cores.
    bool overflows = false, inconsistentHere = false;
    for (int64_t v = b; v < e && !inconsistentHere; ++v)
    {
      const int slots = detail::groupCorners(topology, original, unit.data(), vc, v, cosFeature, s);
      base[static_cast<size_t>(v + 1)] = slots;
      inconsistentHere = inconsistent && !s.fan && detail::hasRepeat(s.next.data(), s.k);
      if (!original)
      {
        overflows = overflows || slots >= recompute;
        const int32_t first = vc.offsets[static_cast<size_t>(v)];
        for (int i = 0; i < s.k; ++i)
        {
          stored[first + i] = slots < recompute ? static_cast<uint16_t>(s.group[i]) : recompute;
        }
      }
    }
    if (overflows)
    {
      overflow = true;
    }
    if (inconsistentHere)
    {
      wrongWay = true;
    }
  });
  if (wrongWay)
  {
    *inconsistent = true;
    return -1;
  }
  for (int64_t v = 0; v < numPoints; ++v)
  {
    base[static_cast<size_t>(v + 1)] += base[static_cast<size_t>(v)];
  }
  const int64_t total = base[static_cast<size_t>(numPoints)];
  if (!original && !overflow)
  {
    unit.reset(); // the stored groups suffice: not held while the output is allocated
  }
  SplitOutput out = allocate(total);

  if (!original && !overflow)
  {
    // Each corner's output point, then a polygon-centric weighted sum.
    parallel.forRange(0, numPoints, 8192, [&](int64_t b, int64_t e) {
      for (int64_t v = b; v < e; ++v)
      {
        for (int32_t i = vc.offsets[static_cast<size_t>(v)]; i < vc.offsets[static_cast<size_t>(v) + 1]; ++i)
        {
          const int64_t id = base[static_cast<size_t>(v)] + stored[static_cast<size_t>(i)];
          outConnectivity[vc.corners[static_cast<size_t>(i)]] = static_cast<OutId>(id);
          out.source[id] = v;
        }
      }
    });
    stored.reset();
    vc.reset();
    // The split's output is allocated after this: large sums are not kept.
    if (!accumulateNormals(topology, outConnectivity, xyz, numPoints, total, weighting, out.normals, parallel,
          shadelab::ScratchPool::LargeBlocks::Free))
    {
      // The corner table was built from these ids, so they were checked.
      throw shadelab::Error("a polygon names a point outside the mesh");
    }
    return total;
  }

  // Welded (or a point with 65535 groups): rebuild the groups point by point.
  parallel.forRange(0, numPoints, 4096, [&](int64_t b, int64_t e) {
    detail::SplitScratch<T> s;
    for (int64_t v = b; v < e; ++v)
    {
      const int32_t first = vc.offsets[static_cast<size_t>(v)];
      const int k = vc.offsets[static_cast<size_t>(v) + 1] - first;
      if (k == 0)
      {
        continue;
      }
      detail::groupCorners(topology, original, unit.data(), vc, v, cosFeature, s);
      s.sums.assign(static_cast<size_t>(k), V(0));
      const V p = point(xyz, v);
      for (int i = 0; i < k; ++i)
      {
        const int64_t c = vc.corners[static_cast<size_t>(first + i)];
        const int64_t f = vc.faceOf(c);
        T len;
        const V u = detail::unitOf(newellVector(topology, xyz, f), len);
        s.sums[static_cast<size_t>(s.group[i])] +=
          cornerContribution(weighting, point(xyz, s.prev[i]), p, point(xyz, s.next[i]), u, len);
      }
      for (int i = 0; i < k; ++i)
      {
        const int64_t id = base[static_cast<size_t>(v)] + (original ? s.slot[i] : s.group[i]);
        T len;
        const V n = detail::unitOf(s.sums[static_cast<size_t>(s.group[i])], len);
        out.normals[3 * id] = static_cast<float>(n.x);
        out.normals[3 * id + 1] = static_cast<float>(n.y);
        out.normals[3 * id + 2] = static_cast<float>(n.z);
        const int64_t c = vc.corners[static_cast<size_t>(first + i)];
        out.source[id] = original ? static_cast<int64_t>(original[c]) : v;
        outConnectivity[c] = static_cast<OutId>(id);
      }
    }
  });
  return total;
}

} // namespace slnormals

#endif
