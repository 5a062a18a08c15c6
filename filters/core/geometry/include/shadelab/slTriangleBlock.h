#ifndef slTriangleBlock_h
#define slTriangleBlock_h
/**
 * @file slTriangleBlock.h
 * @brief Newell vectors and corner weights of a run of consecutive triangles
 * at once, laid out structure-of-arrays so that the compiler vectorises
 * them. VTK-free. Geometry core (ShadeLab::GeometryCore).
 *
 * Gathering a triangle's points is a scattered read, but everything after it
 * (edges, Newell vector, square root, division, three corner angles) is the
 * same arithmetic for every triangle: done in one loop over contiguous
 * arrays, it runs four (float) or two (double) triangles per SSE instruction,
 * eight or four with AVX2. Angle weighting cost about 2.5 times area
 * weighting when each triangle went through two scalar acos one after the
 * other.
 *
 * The loop vectorises only with -fno-math-errno and -fno-trapping-math, which
 * the module's CMakeLists.txt sets: they let sqrt and division run on vectors
 * and change no result. On x86-64, weigh()'s loop is also compiled for AVX2
 * and AVX-512 and picked at run time on CPUs that have them
 * (slVectorClones.h). No version fuses multiply-adds, so all round alike
 * and give the same weights.
 *
 * A block holds consecutive triangles of the connectivity only (triangle i
 * starts at start + 3 i), so it stores no per-triangle position. That is also
 * what keeps GCC 12.2 from miscompiling the scatter loop: with a per-triangle
 * int64 array next to float arrays, -O2 (ivopts) addressed the int64 array
 * as a zero-based memory reference, modref took it for a NULL dereference,
 * concluded the scatter function was pure and deleted its call (all-zero
 * normals with float points; see docs/normals.md).
 */

#include "shadelab/slCompilerHints.h"
#include "shadelab/slVectorClones.h"
#include "slCornerWeights.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

namespace slnormals
{

/// The points and sums a block's triangles will need, asked for ahead (the
/// next block's, while a block is filled). In a large mesh in random order
/// each point a triangle reads and each sum it adds to is a cache miss; asked
/// for one block ahead, the misses overlap with a block's work instead of
/// stalling it. Null ids: nothing is asked for.
template <typename T, typename Id, typename AccId>
struct Lookahead
{
  const Id* pointIds = nullptr;  ///< the triangles' point ids (3 a triangle)
  const AccId* sumIds = nullptr; ///< their sums' entries, same layout
  const T* points = nullptr;     ///< 3 coordinates a point
  const T* sums = nullptr;       ///< 3 components an entry

  /// Asks for the points and sums of triangle @p i. The addresses are
  /// computed in unsigned arithmetic and only hinted, never read, so that
  /// ids not yet checked can do no harm. Always inlined (see slPrefetch()).
  SL_ALWAYS_INLINE void triangle(int i) const
  {
    for (int k = 0; k < 3; ++k)
    {
      const uint64_t point = static_cast<uint64_t>(this->pointIds[3 * i + k]);
      const uint64_t sum = static_cast<uint64_t>(this->sumIds[3 * i + k]);
      slPrefetch(reinterpret_cast<const void*>(reinterpret_cast<uintptr_t>(this->points) + point * (3 * sizeof(T))));
      slPrefetch<true>(reinterpret_cast<const void*>(reinterpret_cast<uintptr_t>(this->sums) + sum * (3 * sizeof(T))));
    }
  }
};

/// What fill() does between groups of four triangles when given nothing else.
struct NothingBetween
{
  SL_ALWAYS_INLINE void operator()(int) const {}
};

/// Up to Capacity consecutive triangles: their points in, the contribution
/// of each corner to its vertex out: corner k of triangle i adds (cornerX,
/// cornerY, cornerZ)[k][i], its weight times the triangle's Newell vector.
template <typename T>
struct TriangleBlock
{
  static constexpr int Capacity = 64;
  int count = 0;
  int64_t start = 0; ///< connectivity position of the first triangle's first corner
  alignas(16) T x[3][Capacity];
  alignas(16) T y[3][Capacity];
  alignas(16) T z[3][Capacity];
  // Products computed with the weights, in the vectorised loop, so that the
  // scatter, a chain of scattered read-add-writes, only adds.
  T cornerX[3][Capacity], cornerY[3][Capacity], cornerZ[3][Capacity];

  /// Whether the triangle at connectivity position @p o can join the block:
  /// it is empty, or @p o directly follows its last triangle.
  bool continues(int64_t o) const { return this->count == 0 || o == this->start + 3 * this->count; }

  /// Appends the triangle at connectivity position @p o (continues(o) must hold).
  template <typename Id>
  void add(const Id* connectivity, const T* xyz, int64_t o)
  {
    if (this->count == 0)
    {
      this->start = o;
    }
    const int i = this->count++;
    for (int k = 0; k < 3; ++k)
    {
      const T* p = xyz + 3 * static_cast<int64_t>(connectivity[o + k]);
      this->x[k][i] = p[0];
      this->y[k][i] = p[1];
      this->z[k][i] = p[2];
    }
  }

  /// Fills the empty block with the @p n (at most Capacity) triangles that
  /// start at connectivity position @p o, one after the other: add() without
  /// the per-triangle bookkeeping. Triangle i also asks @p ahead for its
  /// triangle i (which must hold n triangles when its ids are set). After
  /// each group of four triangles, group g, it calls @p between(g): the
  /// caller's work (another block's scatter, scatterGroup()) that then
  /// waits for memory alongside the gathering instead of after it.
  template <typename Id, typename AccId = Id, typename Between = NothingBetween>
  void fill(const Id* connectivity, const T* xyz, int64_t o, int n, const Lookahead<T, Id, AccId>& ahead = {},
    Between between = {})
  {
    this->start = o;
    this->count = n;
    const Id* ids = connectivity + o;
    for (int i = 0; i < n; ++i, ids += 3)
    {
      if (ahead.pointIds)
      {
        ahead.triangle(i);
      }
      for (int k = 0; k < 3; ++k)
      {
        const T* p = xyz + 3 * static_cast<int64_t>(ids[k]);
        this->x[k][i] = p[0];
        this->y[k][i] = p[1];
        this->z[k][i] = p[2];
      }
      if ((i & 3) == 3)
      {
        between(i >> 2);
      }
    }
  }

  /// fill() for float points when no id is the last point's (numPoints - 1):
  /// a point's coordinates and the next point's x come in one 16-byte load,
  /// and four triangles' corners are transposed into the block at once
  /// (SSE2; fill() elsewhere). @p n must be a multiple of 4.
  template <typename Id, typename AccId = Id, typename Between = NothingBetween>
  void fillBelowLastPoint(const Id* connectivity, const T* xyz, int64_t o, int n,
    const Lookahead<T, Id, AccId>& ahead = {}, Between between = {})
  {
#if defined(__SSE2__)
    if constexpr (std::is_same<T, float>::value)
    {
      this->start = o;
      this->count = n;
      const Id* ids = connectivity + o;
      for (int i = 0; i < n; i += 4, ids += 12)
      {
        if (ahead.pointIds)
        {
          for (int a = i; a < i + 4; ++a)
          {
            ahead.triangle(a);
          }
        }
        for (int k = 0; k < 3; ++k)
        {
          __m128 p0 = _mm_loadu_ps(xyz + 3 * static_cast<int64_t>(ids[k]));
          __m128 p1 = _mm_loadu_ps(xyz + 3 * static_cast<int64_t>(ids[3 + k]));
          __m128 p2 = _mm_loadu_ps(xyz + 3 * static_cast<int64_t>(ids[6 + k]));
          __m128 p3 = _mm_loadu_ps(xyz + 3 * static_cast<int64_t>(ids[9 + k]));
          _MM_TRANSPOSE4_PS(p0, p1, p2, p3);
          _mm_store_ps(&this->x[k][i], p0);
          _mm_store_ps(&this->y[k][i], p1);
          _mm_store_ps(&this->z[k][i], p2);
        }
        between(i >> 2);
      }
      return;
    }
#endif
    this->fill(connectivity, xyz, o, n, ahead, between);
  }

  /// Newell vectors and the weights of @p W (see slCornerWeights.h) of the
  /// count triangles; a degenerate triangle (zero Newell vector) weighs 0.
  /// In the loop's AVX-512 or AVX2 version where the CPU has it.
  template <Weighting W>
  void weigh()
  {
    if (slHasAVX512())
    {
      this->weighAVX512<W>();
    }
    else if (slHasAVX2())
    {
      this->weighAVX2<W>();
    }
    else
    {
      this->weighLoop<W>();
    }
  }

  /// weigh() in its AVX2 version (the CPU must have AVX2).
  template <Weighting W>
  SL_TARGET_AVX2 void weighAVX2()
  {
    this->weighLoop<W>();
  }

  /// weigh() in its AVX-512 version (the CPU must have it, see slHasAVX512()).
  template <Weighting W>
  SL_TARGET_AVX512 void weighAVX512()
  {
    this->weighLoop<W>();
  }

  /// weigh()'s loop, compiled into each version.
  template <Weighting W>
  SL_ALWAYS_INLINE void weighLoop()
  {
    for (int i = 0; i < this->count; ++i)
    {
      // Edges p1 - p0, p2 - p1, p0 - p2; corner k lies between edges k-1 and k.
      const T ax = this->x[1][i] - this->x[0][i], ay = this->y[1][i] - this->y[0][i],
              az = this->z[1][i] - this->z[0][i];
      const T bx = this->x[2][i] - this->x[1][i], by = this->y[2][i] - this->y[1][i],
              bz = this->z[2][i] - this->z[1][i];
      const T cx = this->x[0][i] - this->x[2][i], cy = this->y[0][i] - this->y[2][i],
              cz = this->z[0][i] - this->z[2][i];
      // (p1 - p0) x (p2 - p0) = c x a.
      const T nx = cy * az - cz * ay, ny = cz * ax - cx * az, nz = cx * ay - cy * ax;
      const T nn = nx * nx + ny * ny + nz * nz;
      const bool valid = nn > T(0);
      // Selects, not branches, so that the loop stays vectorisable and trap-free.
      const T zeroOr1 = valid ? T(1) : T(0);
      T w[3];
      if (W == Weighting::Area)
      {
        w[0] = w[1] = w[2] = zeroOr1;
      }
      else if (W == Weighting::Uniform)
      {
        const T len = std::sqrt(nn);
        w[0] = w[1] = w[2] = zeroOr1 / (valid ? len : T(1));
      }
      else if (W == Weighting::Angle)
      {
        // e1 . e2 of each corner's two outgoing edges; |e1 x e2| = len at all three.
        const T len = std::sqrt(nn);
        const T inverse = zeroOr1 / (valid ? len : T(1));
        w[0] = cornerAngle(len, -(cx * ax + cy * ay + cz * az)) * inverse;
        w[1] = cornerAngle(len, -(ax * bx + ay * by + az * bz)) * inverse;
        w[2] = cornerAngle(len, -(bx * cx + by * cy + bz * cz)) * inverse;
      }
      else
      {
        // Max: sin θ / (|e1| |e2|) times the unit normal = N / (|e1|² |e2|²).
        // Below the smallest normal T the reciprocal of |e1|² |e2|² could
        // overflow (and 0 × inf give NaN): such a corner weighs 0, as in
        // maxCornerWeight() (slCornerWeights.h).
        const T la = ax * ax + ay * ay + az * az, lb = bx * bx + by * by + bz * bz,
                lc = cx * cx + cy * cy + cz * cz;
        const T l0 = lc * la, l1 = la * lb, l2 = lb * lc;
        const T smallest = std::numeric_limits<T>::min();
        w[0] = (valid && l0 >= smallest ? T(1) : T(0)) / (l0 >= smallest ? l0 : T(1));
        w[1] = (valid && l1 >= smallest ? T(1) : T(0)) / (l1 >= smallest ? l1 : T(1));
        w[2] = (valid && l2 >= smallest ? T(1) : T(0)) / (l2 >= smallest ? l2 : T(1));
      }
      for (int k = 0; k < 3; ++k)
      {
        this->cornerX[k][i] = nx * w[k];
        this->cornerY[k][i] = ny * w[k];
        this->cornerZ[k][i] = nz * w[k];
      }
    }
  }

  /// Hands every corner's contribution to @p sink: sink.add<Owned>(entry, x,
  /// y, z) with the corner's entry of @p accIds (the connectivity's layout);
  /// @p Owned says the sink owns every entry the block names. The
  /// sink is a small handle taken by value: a copy of its own lets the
  /// compiler keep its fields in registers across the float stores.
  ///
  /// Triangles next to each other in a mesh share vertices, and an update
  /// of a sum right after another of the same sum waits for it (its load
  /// reads what the previous store wrote). So the triangles go in four
  /// interleaved streams, i, i + q, i + 2q, i + 3q: between two updates of
  /// one vertex by neighbours come three other triangles' independent ones.
  template <bool Owned, typename AccId, typename Sink>
  void scatter(const AccId* accIds, Sink sink) const
  {
    const int q = (this->count + 3) / 4;
    for (int j = 0; j < q; ++j)
    {
      this->scatterGroup<Owned>(j, accIds, sink);
    }
  }

  /// Group @p j of scatter(): triangles j, j + q, j + 2q and j + 3q, where
  /// q = (count + 3) / 4. A full block has Capacity / 4 groups, as many as
  /// fill() has groups of four triangles: filling one full block while
  /// adding another's corners group by group mixes the two streams of
  /// cache misses, as a loop that gathers and adds triangle by triangle
  /// does.
  template <bool Owned, typename AccId, typename Sink>
  SL_ALWAYS_INLINE void scatterGroup(int j, const AccId* accIds, Sink& sink) const
  {
    const AccId* to = accIds + this->start;
    const int q = (this->count + 3) / 4;
    for (int i = j; i < this->count; i += q)
    {
      for (int k = 0; k < 3; ++k)
      {
        sink.template add<Owned>(
          static_cast<int64_t>(to[3 * i + k]), this->cornerX[k][i], this->cornerY[k][i], this->cornerZ[k][i]);
      }
    }
  }
};

} // namespace slnormals

#endif
