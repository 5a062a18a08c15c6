// The scratch pool (shadelab/ScratchPool.h) and the arrays taken from it
// (slnormals::ScratchArray): blocks are handed out again, within the
// pool's limit, and a computation that reuses another's scratch memory
// gives the same bits as one on fresh memory.
#include "shadelab/ScratchPool.h"
#include "shadelab/slPolygonNormalsCore.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <random>
#include <thread>
#include <vector>

namespace
{
using shadelab::ScratchPool;

TEST(ScratchPool, AReleasedBlockIsHandedOutAgain)
{
  ScratchPool pool;
  const ScratchPool::Block a = pool.acquire(100000);
  ASSERT_NE(a.data, nullptr);
  EXPECT_GE(a.capacity, 100000u);
  std::memset(a.data, 1, a.capacity); // all of it is usable
  pool.release(a);
  EXPECT_EQ(pool.keptBytes(), a.capacity);
  const ScratchPool::Block b = pool.acquire(90000);
  EXPECT_EQ(b.data, a.data);
  EXPECT_EQ(pool.keptBytes(), 0u);
  pool.release(b);
}

TEST(ScratchPool, AKeptBlockServesASmallerRequest)
{
  ScratchPool pool;
  const ScratchPool::Block big = pool.acquire(size_t(1) << 20);
  pool.release(big);
  const ScratchPool::Block small = pool.acquire(100000);
  EXPECT_EQ(small.data, big.data);
  EXPECT_EQ(small.capacity, big.capacity);
  EXPECT_EQ(pool.keptBytes(), 0u);
  pool.release(small);
  EXPECT_EQ(pool.keptBytes(), big.capacity);
}

TEST(ScratchPool, TheSmallestFittingBlockIsChosen)
{
  ScratchPool pool;
  const ScratchPool::Block a = pool.acquire(300000), b = pool.acquire(200000), c = pool.acquire(400000);
  pool.release(a);
  pool.release(b);
  pool.release(c);
  const ScratchPool::Block d = pool.acquire(190000);
  EXPECT_EQ(d.data, b.data);
  pool.release(d);
}

TEST(ScratchPool, KeepsNoMoreThanItsLimit)
{
  ScratchPool pool(size_t(1) << 20);
  const ScratchPool::Block a = pool.acquire(700000), b = pool.acquire(700000);
  pool.release(a);
  pool.release(b); // would exceed 1 MiB: freed
  EXPECT_EQ(pool.keptBytes(), a.capacity);
  pool.trim();
  EXPECT_EQ(pool.keptBytes(), 0u);
  const ScratchPool::Block c = pool.acquire(700000);
  std::memset(c.data, 2, c.capacity);
  pool.release(c);
}

TEST(ScratchPool, LargeBlocksLieOnHugePageBoundariesAndAreNotKept)
{
  ScratchPool pool;
  const size_t huge = size_t(2) << 20;
  const ScratchPool::Block a = pool.acquire(huge + 1), b = pool.acquire(1000);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(a.data) % huge, 0u);
  EXPECT_EQ(a.capacity, 2 * huge);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(b.data) % 64, 0u);
  EXPECT_EQ(b.capacity, size_t(64) << 10);
  std::memset(a.data, 3, a.capacity);
  std::memset(b.data, 4, b.capacity);
  pool.release(a);
  EXPECT_EQ(pool.keptBytes(), 0u);
  pool.release(b);
  EXPECT_EQ(pool.keptBytes(), b.capacity);
}

TEST(ScratchPool, ALargeBlockIsKeptOnlyWhenItsReleaseSaysSo)
{
  ScratchPool pool;
  const ScratchPool::Block a = pool.acquire(size_t(3) << 20);
  pool.release(a);
  EXPECT_EQ(pool.keptBytes(), 0u);
  const ScratchPool::Block b = pool.acquire(size_t(3) << 20);
  std::memset(b.data, 5, b.capacity);
  pool.release(b, ScratchPool::LargeBlocks::Keep);
  EXPECT_EQ(pool.keptBytes(), b.capacity);
  const ScratchPool::Block c = pool.acquire(size_t(3) << 20);
  EXPECT_EQ(c.data, b.data);
  EXPECT_EQ(pool.keptBytes(), 0u);
  pool.release(c, ScratchPool::LargeBlocks::Keep);
  pool.trim();
  EXPECT_EQ(pool.keptBytes(), 0u);
}

TEST(ScratchPool, AKeptLargeBlockStaysWithinTheLimit)
{
  ScratchPool pool(size_t(4) << 20);
  const ScratchPool::Block a = pool.acquire(size_t(5) << 20);
  pool.release(a, ScratchPool::LargeBlocks::Keep); // 6 MiB: over the limit, freed
  EXPECT_EQ(pool.keptBytes(), 0u);
}

TEST(ScratchPool, ALargeRequestNoKeptBlockFitsFreesTheKeptLargeBlocksFirst)
{
  ScratchPool pool;
  const ScratchPool::Block small = pool.acquire(100000), large = pool.acquire(size_t(3) << 20);
  pool.release(small);
  pool.release(large, ScratchPool::LargeBlocks::Keep);
  EXPECT_EQ(pool.keptBytes(), small.capacity + large.capacity);
  // A request that the large block cannot serve frees it rather than add
  // new memory beside it; the small block stays.
  const ScratchPool::Block larger = pool.acquire(size_t(5) << 20);
  EXPECT_EQ(pool.keptBytes(), small.capacity);
  pool.release(larger);
  EXPECT_EQ(pool.keptBytes(), small.capacity);
  const ScratchPool::Block again = pool.acquire(90000);
  EXPECT_EQ(again.data, small.data);
  pool.release(again);
}

TEST(ScratchPool, FreeingTheLargeBlocksKeepsTheSmallOnes)
{
  ScratchPool pool;
  const ScratchPool::Block a = pool.acquire(size_t(3) << 20), b = pool.acquire(100000),
                           c = pool.acquire(size_t(2) << 20), d = pool.acquire(300000);
  pool.release(a, ScratchPool::LargeBlocks::Keep);
  pool.release(b);
  pool.release(c, ScratchPool::LargeBlocks::Keep);
  pool.release(d);
  EXPECT_EQ(pool.keptBytes(), a.capacity + b.capacity + c.capacity + d.capacity);
  pool.freeLargeBlocks();
  EXPECT_EQ(pool.keptBytes(), b.capacity + d.capacity);
  const ScratchPool::Block e = pool.acquire(250000);
  EXPECT_EQ(e.data, d.data);
  pool.release(e);
}

TEST(ScratchPool, ThreadsShareAPool)
{
  ScratchPool pool(size_t(8) << 20);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
  {
    threads.emplace_back([&pool, t] {
      for (int i = 0; i < 200; ++i)
      {
        const ScratchPool::Block b = pool.acquire(size_t(65536) * (1 + (i + t) % 5));
        std::memset(b.data, t, b.capacity);
        pool.release(b);
      }
    });
  }
  for (std::thread& t : threads)
  {
    t.join();
  }
  EXPECT_LE(pool.keptBytes(), size_t(8) << 20);
  EXPECT_GT(pool.keptBytes(), 0u);
}

TEST(ScratchPool, ScratchArraysGiveTheirMemoryBackOnce)
{
  ScratchPool pool;
  slnormals::Parallel par;
  par.scratch = &pool;
  {
    slnormals::ScratchArray<double> a(par, 10000);
    ASSERT_EQ(a.size(), 10000u);
    a[9999] = 1.0;
    slnormals::ScratchArray<double> b(std::move(a));
    EXPECT_TRUE(a.empty());
    slnormals::ScratchArray<double> c;
    c = std::move(b);
    EXPECT_EQ(c[9999], 1.0);
    EXPECT_EQ(pool.keptBytes(), 0u);
  }
  EXPECT_EQ(pool.keptBytes(), size_t(128) << 10); // 80,000 bytes in 64 KiB steps
  slnormals::ScratchArray<int> none(par, 0);
  EXPECT_TRUE(none.empty());
  EXPECT_EQ(pool.keptBytes(), size_t(128) << 10);
  slnormals::ScratchArray<int> heap(slnormals::Parallel(), 10);
  heap[9] = 9;
  EXPECT_EQ(heap[9], 9);
  const size_t large = size_t(3) << 20;
  {
    slnormals::ScratchArray<char> freed(par, large);
    slnormals::ScratchArray<char> kept(par, large, slnormals::ScratchArray<char>::LargeBlocks::Keep);
    slnormals::ScratchArray<char> moved(std::move(kept)); // the choice moves with the memory
  }
  EXPECT_EQ(pool.keptBytes(), (size_t(128) << 10) + (size_t(4) << 20)); // 3 MiB in 2 MiB pages
}

/// A 400 x 400 grid folded along its columns (creases of 45 and 90 degrees),
/// cut into quads and triangle pairs, plus one point no polygon uses: big
/// enough for the chunked paths, with splits, n-gons and an unused point.
struct FoldedGrid
{
  std::vector<double> xyz;
  std::vector<int64_t> offsets{ 0 }, connectivity;

  FoldedGrid()
  {
    const int n = 400;
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        xyz.insert(xyz.end(), { double(i), double(j), i % 3 == 0 ? 1.0 : 0.0 });
      }
    }
    xyz.insert(xyz.end(), { -5.0, -5.0, 0.0 });
    auto id = [n](int i, int j) { return int64_t(j) * (n + 1) + i; };
    auto add = [this](std::initializer_list<int64_t> ids) {
      connectivity.insert(connectivity.end(), ids);
      offsets.push_back(static_cast<int64_t>(connectivity.size()));
    };
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        if ((i + j) % 3 == 0)
        {
          add({ id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) });
        }
        else
        {
          add({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
          add({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
        }
      }
    }
  }
  /// Puts the polygons in random order (each keeps its corners' order).
  void shuffle(unsigned seed)
  {
    const size_t n = offsets.size() - 1;
    std::vector<size_t> order(n);
    std::iota(order.begin(), order.end(), size_t(0));
    std::shuffle(order.begin(), order.end(), std::mt19937(seed));
    std::vector<int64_t> newOffsets{ 0 }, newConnectivity;
    for (const size_t f : order)
    {
      newConnectivity.insert(newConnectivity.end(), connectivity.begin() + offsets[f], connectivity.begin() + offsets[f + 1]);
      newOffsets.push_back(static_cast<int64_t>(newConnectivity.size()));
    }
    offsets.swap(newOffsets);
    connectivity.swap(newConnectivity);
  }
  slnormals::Polygons<int64_t> polygons()
  {
    return { offsets.data(), connectivity.data(), static_cast<int64_t>(offsets.size()) - 1 };
  }
  int64_t numPoints() const { return static_cast<int64_t>(xyz.size() / 3); }
};

struct Outputs
{
  std::vector<float> normals;
  std::vector<int32_t> connectivity;
  std::vector<int64_t> source, pointMap;
  bool operator==(const Outputs& o) const
  {
    return normals == o.normals && connectivity == o.connectivity && source == o.source && pointMap == o.pointMap;
  }
};

Outputs compute(const slnormals::PolygonNormalsSettings& s, ScratchPool* pool, bool randomOrder = false)
{
  FoldedGrid m;
  if (randomOrder)
  {
    m.shuffle(7);
  }
  slnormals::Parallel par;
  par.threads = 4; // chunks as for four threads, run one after the other
  par.scratch = pool;
  Outputs o;
  slnormals::PolygonNormals<int64_t> r;
  r.allocateNormals = [&](int64_t n) {
    o.normals.assign(static_cast<size_t>(3 * n), 0.0f);
    return o.normals.data();
  };
  r.allocateSplitConnectivity = [&](int64_t n) {
    o.connectivity.assign(static_cast<size_t>(n), 0);
    return o.connectivity.data();
  };
  r.copyPolygons = [&] { return m.polygons(); };
  slnormals::computePolygonNormals(s, m.polygons(), true, m.xyz.data(), m.numPoints(), par, r);
  o.source.assign(r.source.begin(), r.source.end());
  o.pointMap.assign(r.pointMap.begin(), r.pointMap.end());
  return o;
}

TEST(ScratchPool, ComputationsOnReusedScratchGiveTheSameBits)
{
  for (const bool split : { true, false })
  {
    for (const bool weld : { false, true })
    {
      slnormals::PolygonNormalsSettings s;
      s.split = split;
      s.weld = weld;
      const Outputs fresh = compute(s, nullptr);
      // Every interior column is a crease of 45 or 90 degrees: its points split in two.
      ASSERT_EQ(fresh.normals.size(), split ? 3u * (401 * 401 + 399 * 401 + 1) : 3u * (401 * 401 + 1));
      ScratchPool pool(size_t(256) << 20);
      EXPECT_TRUE(compute(s, &pool) == fresh);
      ASSERT_GT(pool.keptBytes(), 0u);
      // Whatever the kept blocks hold, nothing is read before it is written.
      for (const unsigned char poison : { 0xFF, 0x00, 0x7F })
      {
        pool.fillKept(poison);
        EXPECT_TRUE(compute(s, &pool) == fresh) << "split " << split << " weld " << weld << " poison " << int(poison);
      }
    }
  }
}

TEST(ScratchPool, RandomOrderSumsKeptForTheNextComputationGiveTheSameBits)
{
  // In random order, each of the 4 chunks sums into a copy of its own
  // (3.8 MB of doubles each, the first being the accumulator): large
  // blocks, which the pool keeps after a computation without splitting.
  slnormals::PolygonNormalsSettings s;
  s.split = false;
  const Outputs fresh = compute(s, nullptr, true);
  ScratchPool pool(size_t(256) << 20);
  EXPECT_TRUE(compute(s, &pool, true) == fresh);
  const size_t copyBytes = 3 * (401 * 401 + 1) * sizeof(double);
  EXPECT_GE(pool.keptBytes(), 4 * copyBytes);
  const size_t kept = pool.keptBytes();
  for (const unsigned char poison : { 0xFF, 0x00, 0x7F })
  {
    pool.fillKept(poison);
    EXPECT_TRUE(compute(s, &pool, true) == fresh) << "poison " << int(poison);
    EXPECT_EQ(pool.keptBytes(), kept); // the same blocks, taken and given back
  }
  // The same mesh in order gives the same normals up to rounding (sums in another order).
  const Outputs ordered = compute(s, nullptr);
  ASSERT_EQ(ordered.normals.size(), fresh.normals.size());
  for (size_t i = 0; i < fresh.normals.size(); ++i)
  {
    ASSERT_NEAR(fresh.normals[i], ordered.normals[i], 1e-6f) << i;
  }
}
} // namespace
