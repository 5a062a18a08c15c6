#ifndef slVertexNormalsCore_h
#define slVertexNormalsCore_h
/**
 * @file slVertexNormalsCore.h
 * @brief Vertex normals without splitting: weighted face normals summed at
 * each vertex. VTK-free. Geometry core (ShadeLab::GeometryCore).
 *
 * Triangles are weighed in vectorised blocks (slTriangleBlock.h) and their
 * corner contributions added into one accumulator, the output itself when
 * the points are float. The polygons are cut into contiguous chunks, and the
 * entries (points) into as many ranges: chunk k owns range k. A chunk adds a
 * contribution in place when the entry lies in its own range and keeps it
 * in a list for the owner otherwise (a block of triangles whose ids all lie
 * in the range, found by the same vectorised pass that checks the ids, adds
 * without testing each corner); then each range adds the lists kept for
 * it, chunk by chunk, and normalises. No two chunks write the same entry, so
 * there are no atomics, no per-thread copy of the accumulator and no pass
 * that sums copies; the sum order is fixed, so the result does not depend on
 * scheduling.
 *
 * The ranges come from the mesh's order: range k starts at the smallest
 * entry of chunk k's first polygon. In a mesh whose polygons run in the
 * order of their points (what generators, readers and most exporters
 * write) a chunk then reaches outside its range only along its borders, and
 * there are several chunks per thread (up to 8, fewer in small meshes) so
 * that threads that start late still get a share. When a sample of
 * polygons says the order is random (more than a quarter of the corners
 * outside their chunk's range), almost every corner would be kept for
 * another range; then there is one chunk per thread, each summing into its
 * own copy of all entries (chunk 0 into the accumulator), and a pass over
 * the points adds the copies in chunk order and normalises. In a large mesh
 * in random order, where every point and sum is a cache miss, filling a
 * block of triangles asks for the next block's points and sums
 * (kLookaheadEntries).
 *
 * The scatter checks each polygon's point ids before it reads the points
 * they name, so that a caller need not read every id once more beforehand
 * (a pass as long as the scatter's own reading of them): a polygon naming a
 * point outside the mesh stops the computation, which then reports it.
 */

#include "shadelab/slCompilerHints.h"
#include "shadelab/slIdsBelow.h"
#include "shadelab/slVectorClones.h"
#include "slCornerWeights.h"
#include "slFaceNormalsCore.h"
#include "slNormalsParallel.h"
#include "slTriangleBlock.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace slnormals
{

namespace detail
{
/// A contribution a chunk keeps for the owner of its entry: the entry as an
/// offset from the start of the owner's range (ranges hold fewer than 2^31
/// entries).
template <typename T>
struct Kept
{
  uint32_t offset;
  T x, y, z;
};

/// Chunk k's way into the accumulator: entries of its range [lo, hi) are
/// added in place, others kept in kept[owner].
template <typename T>
struct ChunkSink
{
  T* acc;
  int64_t lo, hi;
  const int64_t* bounds; ///< chunks + 1 range starts
  int64_t chunks;
  std::vector<Kept<T>>* kept; ///< one list per owner

  /// Whether @p id lies in [lo, hi): one unsigned compare.
  bool owns(int64_t id) const
  {
    return static_cast<uint64_t>(id - this->lo) < static_cast<uint64_t>(this->hi - this->lo);
  }

  /// Whether this chunk owns every entry: one chunk, or each chunk its own copy.
  bool ownsEverything() const { return this->lo == this->bounds[0] && this->hi == this->bounds[this->chunks]; }

  /// Whether the @p n entries at @p ids all lie in this chunk's range and
  /// below @p below; then add<true>() may skip the test of each one.
  template <typename AccId>
  bool ownsAll(const AccId* ids, int64_t n, int64_t below) const
  {
    return slIdsWithin(ids, n, this->lo, std::min(this->hi, below));
  }

  /// Adds (x, y, z) at entry @p id, in place when this chunk owns it (which
  /// @p Owned asserts), else in the owner's list.
  template <bool Owned = false>
  void add(int64_t id, T x, T y, T z)
  {
    if (Owned || SL_LIKELY(this->owns(id)))
    {
      T* a = this->acc + 3 * id;
      a[0] += x;
      a[1] += y;
      a[2] += z;
      return;
    }
    keep(this->bounds, this->chunks, this->kept, id, x, y, z);
  }

  /// Keeps the contribution for the owner of @p id, in kept[owner]. Out of
  /// line and given the fields by value: inlined, it took registers from
  /// the hot path, and given the sink itself, it made the compiler reload
  /// the accumulator's address after every update (27 of 175 instructions
  /// a triangle, callgrind).
  SL_NOINLINE static void keep(
    const int64_t* bounds, int64_t chunks, std::vector<Kept<T>>* kept, int64_t id, T x, T y, T z)
  {
    const int64_t owner = std::upper_bound(bounds + 1, bounds + chunks + 1, id) - (bounds + 1);
    kept[owner].push_back({ static_cast<uint32_t>(id - bounds[owner]), x, y, z });
  }
};

/// Whether polygons [f, f + n) are triangles, each right after the other:
/// whether offset f + i is offset f + 3 i for every i up to n. The
/// differences are or-ed together, without a compare or a branch, so that
/// the loop vectorises (SSE2 subtracts 64-bit lanes; it has no 64-bit
/// compare). The expected offset grows by 3 a step rather than being
/// computed as 3 i: SSE2 has no 64-bit multiply either, and GCC 12 left the
/// loop with the multiply scalar. Unsigned arithmetic wraps, and offsets
/// differ by less than its range, so a zero difference is an equal offset.
template <typename Id>
bool consecutiveTriangles(const Polygons<Id>& polys, int64_t f, int64_t n)
{
  using U = std::make_unsigned_t<Id>;
  const Id* o = polys.offsets + f;
  U expected = static_cast<U>(o[0]);
  U differences = 0;
  for (int64_t i = 1; i <= n; ++i)
  {
    expected += 3;
    differences |= static_cast<U>(static_cast<U>(o[i]) - expected);
  }
  return differences == 0;
}

/// How many blocks ahead the scatter asks for the polygons' ids. Reading
/// them is sequential, but the scatter's own misses (its points and sums)
/// take the cache's line fill buffers and the hardware's prefetching falls
/// behind: on the bench's shuffled torus of 0.5M triangles, two threads,
/// the pass that reads a block's ids (slIdsWithin) had 19 % of the samples
/// of `perf record`, 85 % of them at its loads. Asking 2 blocks ahead (updates
/// in a loop, alternating with a build that does not ask): 0.84 of the time
/// there (one thread 0.81), 0.93-0.97 at 0.5M, 2M and 8M in order, 0.99-1.01
/// at 0.1M and at 2M and 8M shuffled, whose Lookahead already reads the
/// next block's ids, and no change with splitting.
constexpr int64_t kIdsAheadBlocks = 2;

/// Asks for the offsets, point ids and (when apart) entries of the block
/// kIdsAheadBlocks ahead of the block of consecutive triangles at polygon
/// @p f, whose ids start at @p ids. Addresses are only hinted: a polygon
/// ahead that is not a triangle makes them a guess, not a fault.
template <int capacity, typename Id, typename AccId>
SL_ALWAYS_INLINE void askForIdsAhead(const Polygons<Id>& polys, const AccId* accIds, int64_t f, const Id* ids)
{
  constexpr int64_t corners = 3 * kIdsAheadBlocks * capacity;
  const auto ahead = [](const void* at, int64_t items, size_t itemSize) {
    return reinterpret_cast<const void*>(reinterpret_cast<uintptr_t>(at) + static_cast<uintptr_t>(items) * itemSize);
  };
  slPrefetchBytes(ahead(polys.offsets + f, kIdsAheadBlocks * capacity, sizeof(Id)), capacity * sizeof(Id));
  slPrefetchBytes(ahead(ids, corners, sizeof(Id)), 3 * capacity * sizeof(Id));
  if (static_cast<const void*>(accIds) != static_cast<const void*>(polys.connectivity))
  {
    const AccId* to = accIds + (ids - polys.connectivity);
    slPrefetchBytes(ahead(to, corners, sizeof(AccId)), 3 * capacity * sizeof(AccId));
  }
}

/// Hands the corner contributions of polygons [b, e) to @p sink at the
/// corners' entries of @p accIds (same layout as the connectivity). Runs of
/// consecutive triangles go through TriangleBlock; other polygons one by one.
/// With @p lookahead, filling a block asks for the next block's points and
/// sums (see Lookahead). False, at the first polygon naming a point outside
/// [0, @p numPoints) of @p xyz, without reading it: the sums are then
/// incomplete.
template <Weighting W, typename T, typename Id, typename AccId, typename Sink>
bool scatter(const Polygons<Id>& polys, const AccId* accIds, const T* xyz, int64_t numPoints, int64_t b, int64_t e,
  bool lookahead, Sink& sink)
{
  using V = glm::vec<3, T>;
  constexpr int capacity = TriangleBlock<T>::Capacity;
  // With @p lookahead (a large mesh in random order), a full block is
  // weighed and its corners are added while the next full block is filled
  // (TriangleBlock::scatterGroup()), so that the misses of the sums it adds
  // to wait alongside those of the points being gathered. In a loop of
  // updates on two threads, that took 0.86 of the time of adding a block's
  // corners right after weighing it at 2M shuffled triangles, about the
  // same at 0.5M shuffled (no lookahead there), and 1.10 at 0.5M and 2M in
  // order, whose misses are few: so only with lookahead.
  TriangleBlock<T> blocks[2];
  TriangleBlock<T>* block = blocks;     // the one being filled
  TriangleBlock<T>* weighed = nullptr;  // full and weighed, its corners not yet added
  bool weighedOwned = false;
  const bool ownsEverything = sink.ownsEverything();
  // Adds the corners of @p b; owned says the sums it adds to are all the
  // chunk's own, so that no corner is tested.
  const auto addCorners = [&](const TriangleBlock<T>& b, bool owned) {
    if (owned)
    {
      b.template scatter<true>(accIds, sink);
    }
    else
    {
      b.template scatter<false>(accIds, sink);
    }
  };
  // flush(owned): weighs the block being filled and adds its corners.
  const auto flush = [&](bool owned) {
    block->template weigh<W>();
    addCorners(*block, owned);
    block->count = 0;
  };
  // When the entries are the points themselves and the chunk's range lies
  // among them, one pass over a block's ids asks both whether they name
  // points (the bad-id check) and whether the chunk owns them all, the
  // common case in a mesh in order.
  const bool idsAreEntries = std::is_same<Id, AccId>::value &&
    static_cast<const void*>(accIds) == static_cast<const void*>(polys.connectivity) && sink.hi <= numPoints;
  for (int64_t f = b; f < e; ++f)
  {
    // A whole block of triangles one after the other is filled in one go:
    // the common case of a triangle mesh.
    if (block->count == 0 && e - f >= capacity && consecutiveTriangles(polys, f, capacity))
    {
      const Id* ids = polys.connectivity + polys.begin(f);
      if (f + (kIdsAheadBlocks + 1) * capacity <= e)
      {
        askForIdsAhead<capacity>(polys, accIds, f, ids);
      }
      const bool inRange = idsAreEntries && sink.ownsAll(ids, 3 * capacity, numPoints - 1);
      // Otherwise (the split's output ids, or a block at a range's border)
      // the check asks for ids below the last point, which lets the block
      // be read in 16-byte loads; only a block naming the last point or
      // beyond needs a second look.
      const bool belowLast = inRange || slIdsBelow(ids, 3 * capacity, numPoints - 1);
      if (!belowLast && !slIdsBelow(ids, 3 * capacity, numPoints))
      {
        return false;
      }
      // The next block's ids are read only where the connectivity holds them.
      Lookahead<T, Id, AccId> ahead;
      if (lookahead && f + 2 * capacity <= e)
      {
        const int64_t next = polys.begin(f + capacity);
        if (next + 3 * capacity <= polys.begin(polys.numPolygons))
        {
          ahead = { polys.connectivity + next, accIds + next, xyz, sink.acc };
        }
      }
      const auto fillBlock = [&](auto between) {
        if (belowLast)
        {
          block->fillBelowLastPoint(polys.connectivity, xyz, polys.begin(f), capacity, ahead, between);
        }
        else
        {
          block->fill(polys.connectivity, xyz, polys.begin(f), capacity, ahead, between);
        }
      };
      if (!lookahead)
      {
        fillBlock(NothingBetween());
        flush(ownsEverything || inRange);
        f += capacity - 1;
        continue;
      }
      if (!weighed)
      {
        fillBlock(NothingBetween());
      }
      else if (weighedOwned)
      {
        fillBlock([&](int group) { weighed->template scatterGroup<true>(group, accIds, sink); });
      }
      else
      {
        fillBlock([&](int group) { weighed->template scatterGroup<false>(group, accIds, sink); });
      }
      block->template weigh<W>();
      // The block just weighed waits for the next fill; the one whose
      // corners that fill added (or, the first time, the other) is filled next.
      TriangleBlock<T>* emptied = weighed ? weighed : (block == blocks ? blocks + 1 : blocks);
      emptied->count = 0;
      weighed = block;
      weighedOwned = ownsEverything || inRange;
      block = emptied;
      f += capacity - 1;
      continue;
    }
    const int64_t o = polys.begin(f);
    const int64_t n = polys.size(f);
    if (n == 3)
    {
      if (!slIdsBelowInline(polys.connectivity + o, 3, numPoints))
      {
        return false;
      }
      if (!block->continues(o))
      {
        flush(ownsEverything);
      }
      block->add(polys.connectivity, xyz, o);
      if (block->count == capacity)
      {
        flush(ownsEverything);
      }
      continue;
    }
    if (!slIdsBelowInline(polys.connectivity + o, n, numPoints))
    {
      return false;
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
      const V c = cornerContribution(W, prev, point(xyz, ids[i]), next, u, len);
      sink.add(static_cast<int64_t>(to[i]), c.x, c.y, c.z);
    }
  }
  if (weighed)
  {
    addCorners(*weighed, weighedOwned);
  }
  if (block->count > 0)
  {
    flush(ownsEverything);
  }
  return true;
}

/// A mesh in random order with at least this many entries asks for each
/// block's points and sums one block ahead (Lookahead). The misses cost most
/// once the points and sums (24 bytes an entry with float points) outgrow
/// the 1 MiB L2 cache many times over: on the bench's shuffled torus, two
/// threads, asking took 0.69-0.75 of the time at 2M triangles (1M points)
/// and 0.81-0.87 at 8M, 0.83-1.03 at 0.5M (250,000 points), and 1.09-1.10
/// at 0.1M (50,000 points, in cache, where asking only costs instructions).
/// Asking for each triangle's points and sums 16 triangles ahead, triangle
/// by triangle instead of block by block, was 7-30 % slower than not asking.
constexpr int64_t kLookaheadEntries = int64_t(1) << 18;

/// Chunks of a mesh in order hold at least this many polygons, unless that
/// leaves fewer than 2 per thread. On two threads, updates in a loop took
/// 0.41 ms instead of 0.44-0.53 at 0.1M triangles (4 chunks instead of 16)
/// and 2.36-2.40 ms instead of 2.41-2.73 at 0.5M (7 instead of 16).
constexpr int64_t kMinChunkPolygons = 65536;

/// Chunks of polygons and the entry ranges they own (see the file comment).
struct Partition
{
  int64_t chunks = 1;
  std::vector<int64_t> bounds; ///< chunks + 1: range k is [bounds[k], bounds[k + 1])
  double keptShare = 0;        ///< estimated share of corners outside their chunk's range
  bool randomOrder = false;    ///< the sample found no locality: a copy of the sums per chunk

  template <typename Id>
  int64_t firstPolygon(const Polygons<Id>& polys, int64_t k) const
  {
    return polys.numPolygons * k / this->chunks;
  }
};

/// Splits @p polys (entries @p accIds, in [0, numEntries)) for @p threads threads.
template <typename Id, typename AccId>
Partition partition(const Polygons<Id>& polys, const AccId* accIds, int64_t numEntries, int threads)
{
  Partition p;
  const int64_t maxRange = int64_t(1) << 31;
  // Ranges of equal size, for @p chunks chunks.
  const auto evenly = [&](int64_t chunks) {
    p.chunks = std::max<int64_t>(chunks, 1 + numEntries / maxRange);
    p.bounds.resize(static_cast<size_t>(p.chunks + 1));
    for (int64_t k = 0; k <= p.chunks; ++k)
    {
      p.bounds[static_cast<size_t>(k)] = numEntries * k / p.chunks;
    }
    p.keptShare = static_cast<double>(p.chunks - 1) / static_cast<double>(p.chunks);
  };
  if (polys.numPolygons < 65536)
  {
    evenly(1);
    return p;
  }
  // In mesh order: range k starts at the smallest entry of chunk k's first
  // polygon (with at least 16 chunks, also on one thread, for the sample).
  const auto inMeshOrder = [&](int64_t chunks) {
    p.chunks = chunks;
    p.bounds.assign(static_cast<size_t>(p.chunks + 1), 0);
    p.bounds[static_cast<size_t>(p.chunks)] = numEntries;
    for (int64_t k = 1; k < p.chunks; ++k)
    {
      const int64_t f = p.firstPolygon(polys, k);
      int64_t smallest = numEntries;
      for (int64_t c = polys.begin(f); c < polys.end(f); ++c)
      {
        smallest = std::min<int64_t>(smallest, static_cast<int64_t>(accIds[c]));
      }
      p.bounds[static_cast<size_t>(k)] = std::max(p.bounds[static_cast<size_t>(k - 1)], smallest);
    }
  };
  inMeshOrder(std::min<int64_t>(8 * std::max(threads, 2), 64));
  // A sample of 16 polygons per chunk: how many corners fall outside the range.
  int64_t outside = 0, sampled = 0;
  bool tooLarge = false;
  for (int64_t k = 0; k < p.chunks; ++k)
  {
    const int64_t lo = p.bounds[static_cast<size_t>(k)], hi = p.bounds[static_cast<size_t>(k + 1)];
    tooLarge = tooLarge || hi - lo >= maxRange;
    const int64_t b = p.firstPolygon(polys, k), e = p.firstPolygon(polys, k + 1);
    for (int s = 0; s < 16; ++s)
    {
      const int64_t f = b + (e - b) * s / 16;
      for (int64_t c = polys.begin(f); c < polys.end(f); ++c)
      {
        const int64_t id = static_cast<int64_t>(accIds[c]);
        outside += id < lo || id >= hi;
        ++sampled;
      }
    }
  }
  p.keptShare = sampled ? static_cast<double>(outside) / static_cast<double>(sampled) : 0.0;
  p.randomOrder = p.keptShare > 0.25;
  if (threads <= 1 || p.randomOrder || tooLarge)
  {
    // One thread: one chunk. Random order: one chunk per thread, the
    // entries split evenly.
    evenly(std::max(threads, 1));
  }
  else
  {
    // Fewer chunks for a small mesh: each chunk costs a start, its lists
    // and the corners along its border.
    const int64_t fewer = std::max<int64_t>(2 * threads, polys.numPolygons / kMinChunkPolygons);
    const int64_t sampledChunks = p.chunks;
    if (fewer < sampledChunks)
    {
      inMeshOrder(fewer);
      bool widerThanOffsets = false; // a Kept offset is 32-bit
      for (int64_t k = 0; k < p.chunks; ++k)
      {
        const int64_t width = p.bounds[static_cast<size_t>(k + 1)] - p.bounds[static_cast<size_t>(k)];
        widerThanOffsets = widerThanOffsets || width >= maxRange;
      }
      if (widerThanOffsets)
      {
        inMeshOrder(sampledChunks);
      }
      else
      {
        // About as many corners cross each border.
        p.keptShare *= static_cast<double>(fewer - 1) / static_cast<double>(sampledChunks - 1);
      }
    }
  }
  return p;
}

/// @p o (3 floats) = (x, y, z) / |(x, y, z)|; a zero sum stays zero.
/// Selects, not branches, so that the loops below vectorise.
template <typename T>
SL_ALWAYS_INLINE void storeUnit(T x, T y, T z, float* o)
{
  const T len = std::sqrt(x * x + y * y + z * z);
  const T divisor = len > T(0) ? len : T(1);
  o[0] = static_cast<float>(x / divisor);
  o[1] = static_cast<float>(y / divisor);
  o[2] = static_cast<float>(z / divisor);
}

/// Entries [lo, hi) of @p sums, normalised into @p out (which they do not
/// overlap).
template <typename T>
SL_ALWAYS_INLINE void normaliseInto(const T* __restrict sums, float* __restrict out, int64_t lo, int64_t hi)
{
  for (int64_t v = lo; v < hi; ++v)
  {
    storeUnit(sums[3 * v], sums[3 * v + 1], sums[3 * v + 2], out + 3 * v);
  }
}

/// Entries [lo, hi) of float @p sums normalised in place: one pointer, so
/// that the compiler sees each entry read before it is written and
/// vectorises without a run-time overlap test (which in place would fail).
SL_ALWAYS_INLINE void normaliseInPlace(float* sums, int64_t lo, int64_t hi)
{
  for (int64_t v = lo; v < hi; ++v)
  {
    storeUnit(sums[3 * v], sums[3 * v + 1], sums[3 * v + 2], sums + 3 * v);
  }
}

/// Entries [lo, hi) of @p sums normalised into @p out, which is either
/// @p sums itself (float sums) or an array apart from it.
template <typename T>
SL_ALWAYS_INLINE void normaliseLoop(const T* sums, float* out, int64_t lo, int64_t hi)
{
  if constexpr (std::is_same<T, float>::value)
  {
    if (sums == out)
    {
      normaliseInPlace(out, lo, hi);
      return;
    }
  }
  normaliseInto(sums, out, lo, hi);
}

template <typename T>
SL_TARGET_AVX2 void normaliseSumsAVX2(const T* sums, float* out, int64_t lo, int64_t hi)
{
  normaliseLoop(sums, out, lo, hi);
}

template <typename T>
SL_TARGET_AVX512 void normaliseSumsAVX512(const T* sums, float* out, int64_t lo, int64_t hi)
{
  normaliseLoop(sums, out, lo, hi);
}

/// normaliseLoop(), with 16 or 8 square roots and divisions at once where
/// the CPU has AVX-512 or AVX2 (in cache, AVX-512 takes 0.54 of AVX2's time
/// on a Zen 5).
template <typename T>
void normaliseSums(const T* sums, float* out, int64_t lo, int64_t hi)
{
  if (slHasAVX512())
  {
    normaliseSumsAVX512(sums, out, lo, hi);
  }
  else if (slHasAVX2())
  {
    normaliseSumsAVX2(sums, out, lo, hi);
  }
  else
  {
    normaliseLoop(sums, out, lo, hi);
  }
}

/// @p sums[i] += @p more[i] for i in [0, n).
template <typename T>
void addInto(T* __restrict sums, const T* __restrict more, int64_t n)
{
  for (int64_t i = 0; i < n; ++i)
  {
    sums[i] += more[i];
  }
}

/// Where the sums go: the float output itself when the points are float,
/// else a scratch array of T (null: allocate one).
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

/// Normalised sums of corner contributions of @p polys over the @p numPoints
/// points @p xyz, into @p out (3 floats an entry), at the entries @p accIds
/// (the connectivity's layout, values in [0, numEntries), checked by the
/// caller). Entries no non-degenerate corner reaches get (0, 0, 0). False,
/// and @p out incomplete, when a polygon names a point outside
/// [0, numPoints): the points it names are not read. @p sumsKept: whether
/// the pool may keep the scratch sums, large ones too, for the next
/// computation (ScratchPool::LargeBlocks::Keep): only when the caller
/// allocates nothing after this call.
template <typename T, typename Id, typename AccId>
[[nodiscard]] bool accumulateNormals(const Polygons<Id>& polys, const AccId* accIds, const T* xyz, int64_t numPoints,
  int64_t numEntries, Weighting weighting, float* out, const Parallel& parallel,
  shadelab::ScratchPool::LargeBlocks sumsKept)
{
  const detail::Partition part = detail::partition(polys, accIds, numEntries, parallel.threads);
  const int64_t chunks = part.chunks;
  const int64_t* bounds = part.bounds.data();
  ScratchArray<T> scratch;
  T* acc = detail::inPlaceAccumulator<T>(out);
  if (!acc)
  {
    scratch = ScratchArray<T>(parallel, static_cast<size_t>(3 * numEntries), sumsKept);
    acc = scratch.data();
  }
  // Random order: half or more of a chunk's corners would be kept for other
  // ranges, which cost more than they save; each chunk sums into its own
  // copy of all entries instead (chunk 0 into acc), added in chunk order.
  const bool copies = part.randomOrder && chunks > 1;
  const bool lookahead = part.randomOrder && numEntries >= detail::kLookaheadEntries;
  std::vector<ScratchArray<T>> copy(static_cast<size_t>(copies ? chunks : 0));
  // kept[k * chunks + j]: what chunk k keeps for range j.
  std::vector<std::vector<detail::Kept<T>>> kept(static_cast<size_t>(chunks * chunks));
  std::atomic<bool> badIds(false);
  parallel.forRange(0, chunks, 1, [&](int64_t kb, int64_t ke) {
    for (int64_t k = kb; k < ke; ++k)
    {
      int64_t lo = bounds[k], hi = bounds[k + 1];
      T* sums = acc;
      if (copies)
      {
        lo = 0;
        hi = numEntries;
        if (k > 0)
        {
          copy[static_cast<size_t>(k)] = ScratchArray<T>(parallel, static_cast<size_t>(3 * numEntries), sumsKept);
          sums = copy[static_cast<size_t>(k)].data();
        }
      }
      std::fill(sums + 3 * lo, sums + 3 * hi, T(0));
      const int64_t b = part.firstPolygon(polys, k), e = part.firstPolygon(polys, k + 1);
      std::vector<detail::Kept<T>>* mine = kept.data() + k * chunks;
      if (!copies && part.keptShare > 0 && chunks > 1)
      {
        const double corners = static_cast<double>(e > b ? polys.begin(e) - polys.begin(b) : 0);
        const auto expected = static_cast<size_t>(corners * part.keptShare / static_cast<double>(chunks - 1) * 1.05);
        for (int64_t j = 0; j < chunks; ++j)
        {
          if (j != k)
          {
            mine[j].reserve(expected);
          }
        }
      }
      detail::ChunkSink<T> sink{ sums, lo, hi, bounds, chunks, mine };
      const auto run = [&](auto weightingTag) {
        constexpr Weighting w = decltype(weightingTag)::value;
        return detail::scatter<w>(polys, accIds, xyz, numPoints, b, e, lookahead, sink);
      };
      bool done = false;
      switch (weighting)
      {
        case Weighting::Uniform:
          done = run(std::integral_constant<Weighting, Weighting::Uniform>());
          break;
        case Weighting::Area:
          done = run(std::integral_constant<Weighting, Weighting::Area>());
          break;
        case Weighting::Angle:
          done = run(std::integral_constant<Weighting, Weighting::Angle>());
          break;
        case Weighting::Max:
          done = run(std::integral_constant<Weighting, Weighting::Max>());
          break;
      }
      if (!done)
      {
        badIds.store(true, std::memory_order_relaxed);
      }
    }
  });
  if (badIds.load())
  {
    return false;
  }
  if (copies)
  {
    // Piece by piece, so that a piece's sums are still in cache for the
    // second loop: the copies added into acc in chunk order (flat loops,
    // which vectorise), then normalised as without copies.
    parallel.forRange(0, numEntries, 16384, [&](int64_t b, int64_t e) {
      for (int64_t k = 1; k < chunks; ++k)
      {
        detail::addInto(acc + 3 * b, copy[static_cast<size_t>(k)].data() + 3 * b, 3 * (e - b));
      }
      detail::normaliseSums(acc, out, b, e);
    });
    return true;
  }
  parallel.forRange(0, chunks, 1, [&](int64_t jb, int64_t je) {
    for (int64_t j = jb; j < je; ++j)
    {
      const int64_t lo = bounds[j], hi = bounds[j + 1];
      T* base = acc + 3 * lo;
      for (int64_t k = 0; k < chunks; ++k)
      {
        const std::vector<detail::Kept<T>>& list = kept[static_cast<size_t>(k * chunks + j)];
        for (size_t i = 0; i < list.size(); ++i)
        {
          if (i + 16 < list.size())
          {
            slPrefetch<true>(base + 3 * static_cast<int64_t>(list[i + 16].offset));
          }
          const detail::Kept<T>& c = list[i];
          T* a = base + 3 * static_cast<int64_t>(c.offset);
          a[0] += c.x;
          a[1] += c.y;
          a[2] += c.z;
        }
        std::vector<detail::Kept<T>>().swap(kept[static_cast<size_t>(k * chunks + j)]);
      }
      detail::normaliseSums(acc, out, lo, hi);
    }
  });
  return true;
}

/// Unit vertex normals of points [0, numPoints) into @p out (3 floats each).
/// Points used by no non-degenerate polygon get (0, 0, 0). False, and
/// @p out incomplete, when a polygon names a point outside [0, numPoints)
/// (not read). The pool may keep the scratch sums, however large, for the
/// next computation: a caller that allocates afterwards first frees them
/// (ScratchPool::freeLargeBlocks()), so that they never sit idle beside new
/// memory. In a mesh in random order they are a copy of the sums per extra
/// thread, freshly mapped on every update otherwise.
template <typename T, typename Id>
[[nodiscard]] bool computeVertexNormals(const Polygons<Id>& polys, const T* xyz, int64_t numPoints,
  Weighting weighting, float* out, const Parallel& parallel)
{
  return accumulateNormals(polys, polys.connectivity, xyz, numPoints, numPoints, weighting, out, parallel,
    shadelab::ScratchPool::LargeBlocks::Keep);
}

} // namespace slnormals

#endif
