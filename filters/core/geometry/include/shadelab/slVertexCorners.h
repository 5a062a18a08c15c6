#ifndef slVertexCorners_h
#define slVertexCorners_h
/**
 * @file slVertexCorners.h
 * @brief For every point, the polygon corners at it (a compressed sparse row
 * table). VTK-free. Geometry core (ShadeLab::GeometryCore).
 *
 * Corners are positions in the connectivity array, stored as 32-bit integers:
 * meshes with 2^31 or more corners are refused by the callers.
 */

#include "slNormalsParallel.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <vector>

namespace slnormals
{

template <typename Id>
struct VertexCorners
{
  ScratchArray<int32_t> offsets;    ///< numPoints + 1
  ScratchArray<int32_t> corners;    ///< connectivity positions, grouped by point
  ScratchArray<int32_t> cornerFace; ///< polygon of each position (empty if all triangles)
  bool allTriangles = false;

  int64_t faceOf(int64_t corner) const
  {
    return this->allTriangles ? corner / 3 : this->cornerFace[static_cast<size_t>(corner)];
  }

  /// A corner's polygon and the connectivity positions of the corners before
  /// and after it there.
  struct Around
  {
    int64_t face, prev, next;
  };

  /// Around of connectivity position @p c; reads no offset for triangles.
  Around around(const Polygons<Id>& polys, int64_t c) const
  {
    if (this->allTriangles)
    {
      const int64_t f = c / 3, b = 3 * f;
      return { f, c == b ? b + 2 : c - 1, c == b + 2 ? b : c + 1 };
    }
    const int64_t f = this->cornerFace[static_cast<size_t>(c)];
    const int64_t b = polys.begin(f), e = polys.end(f);
    return { f, c == b ? e - 1 : c - 1, c + 1 == e ? b : c + 1 };
  }

  /// Fills the table for @p polys. Parallel counting sort: each chunk of
  /// corners counts its points, chunk k's corners go after chunks 0..k-1's
  /// at every point, so the table is the same as a serial build's (corners
  /// in increasing order at every point) whatever the thread count.
  void build(const Polygons<Id>& polys, int64_t numPoints, const Parallel& parallel)
  {
    const int64_t numCorners = polys.numPolygons ? polys.end(polys.numPolygons - 1) : 0;
    this->allTriangles = numCorners == 3 * polys.numPolygons && allOfSize3(polys, parallel);
    if (!this->allTriangles)
    {
      this->cornerFace = ScratchArray<int32_t>(parallel, static_cast<size_t>(numCorners));
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
      this->cornerFace.reset();
    }
    const Id* conn = polys.connectivity;
    const int64_t chunks =
      numCorners < (int64_t(1) << 18) ? 1 : std::max<int64_t>(1, std::min<int64_t>(parallel.threads, 8));
    auto chunkBegin = [&](int64_t k) { return numCorners * k / chunks; };
    // cursor[k][v]: corners of chunk k at point v, then where the next one
    // goes. Chunk 0 counts in the offsets themselves, which then hold where
    // its corners go, and are put back after the fill: one array of a point
    // each fewer.
    this->offsets = ScratchArray<int32_t>(parallel, static_cast<size_t>(numPoints + 1));
    std::vector<ScratchArray<int32_t>> others(static_cast<size_t>(chunks - 1));
    std::vector<int32_t*> cursor(static_cast<size_t>(chunks), this->offsets.data());
    for (int64_t k = 1; k < chunks; ++k)
    {
      others[static_cast<size_t>(k - 1)] = ScratchArray<int32_t>(parallel, static_cast<size_t>(numPoints));
      cursor[static_cast<size_t>(k)] = others[static_cast<size_t>(k - 1)].data();
    }
    parallel.forRange(0, chunks, 1, [&](int64_t kb, int64_t ke) {
      for (int64_t k = kb; k < ke; ++k)
      {
        int32_t* count = cursor[static_cast<size_t>(k)];
        std::fill(count, count + numPoints, 0);
        for (int64_t c = chunkBegin(k); c < chunkBegin(k + 1); ++c)
        {
          ++count[conn[c]];
        }
      }
    });
    // Where each chunk's corners start at each point, by a two-pass
    // parallel prefix sum over blocks of points.
    const int64_t block = 65536;
    const int64_t numBlocks = (numPoints + block - 1) / block;
    std::vector<int64_t> blockStart(static_cast<size_t>(numBlocks + 1), 0);
    parallel.forRange(0, numBlocks, 1, [&](int64_t bb, int64_t be) {
      for (int64_t i = bb; i < be; ++i)
      {
        int64_t sum = 0;
        for (int64_t v = i * block; v < std::min(numPoints, (i + 1) * block); ++v)
        {
          for (const int32_t* count : cursor)
          {
            sum += count[v];
          }
        }
        blockStart[static_cast<size_t>(i + 1)] = sum;
      }
    });
    for (int64_t i = 0; i < numBlocks; ++i)
    {
      blockStart[static_cast<size_t>(i + 1)] += blockStart[static_cast<size_t>(i)];
    }
    parallel.forRange(0, numBlocks, 1, [&](int64_t bb, int64_t be) {
      for (int64_t i = bb; i < be; ++i)
      {
        int64_t next = blockStart[static_cast<size_t>(i)];
        for (int64_t v = i * block; v < std::min(numPoints, (i + 1) * block); ++v)
        {
          for (int32_t* at : cursor)
          {
            const int32_t n = at[v];
            at[v] = static_cast<int32_t>(next);
            next += n;
          }
        }
      }
    });
    this->corners = ScratchArray<int32_t>(parallel, static_cast<size_t>(numCorners));
    parallel.forRange(0, chunks, 1, [&](int64_t kb, int64_t ke) {
      for (int64_t k = kb; k < ke; ++k)
      {
        int32_t* next = cursor[static_cast<size_t>(k)];
        for (int64_t c = chunkBegin(k); c < chunkBegin(k + 1); ++c)
        {
          this->corners[static_cast<size_t>(next[conn[c]]++)] = static_cast<int32_t>(c);
        }
      }
    });
    // The last chunk's cursor at v now stands where point v + 1 starts.
    int32_t* o = this->offsets.data();
    if (chunks == 1)
    {
      std::memmove(o + 1, o, static_cast<size_t>(numPoints) * sizeof(int32_t));
    }
    else
    {
      const int32_t* last = cursor.back();
      parallel.forRange(1, numPoints, 65536, [&](int64_t b, int64_t e) {
        for (int64_t v = b; v < e; ++v)
        {
          o[v] = last[v - 1];
        }
      });
    }
    o[0] = 0;
    o[numPoints] = static_cast<int32_t>(numCorners);
  }

  /// Gives the table's memory back; the table is then empty.
  void reset() noexcept
  {
    this->offsets.reset();
    this->corners.reset();
    this->cornerFace.reset();
  }

  /// How many points of the table (built on numPoints points) have no
  /// corner: the points used by no polygon.
  int64_t pointsWithoutCorners(const Parallel& parallel) const
  {
    const int64_t numPoints = static_cast<int64_t>(this->offsets.size()) - 1;
    std::atomic<int64_t> count{ 0 };
    parallel.forRange(0, numPoints, 65536, [&](int64_t b, int64_t e) {
      int64_t none = 0;
      for (int64_t v = b; v < e; ++v)
      {
        none += this->offsets[static_cast<size_t>(v) + 1] == this->offsets[static_cast<size_t>(v)];
      }
      count += none;
    });
    return count;
  }

private:
  /// True if every polygon has three corners (the corner count alone would
  /// take a 2-gon and a 4-gon for two triangles).
  static bool allOfSize3(const Polygons<Id>& polys, const Parallel& parallel)
  {
    std::atomic<bool> other{ false };
    parallel.forRange(0, polys.numPolygons, 65536, [&](int64_t b, int64_t e) {
      for (int64_t f = b; f < e && !other.load(std::memory_order_relaxed); ++f)
      {
        if (polys.size(f) != 3)
        {
          other = true;
        }
      }
    });
    return !other;
  }
};

} // namespace slnormals

#endif
