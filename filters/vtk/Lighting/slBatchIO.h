#ifndef slBatchIO_h
#define slBatchIO_h
/**
 * @file slBatchIO.h
 * @brief Internal: moves 8 consecutive xyz tuples of a flat float array
 * (VTK's layout, array of structures) into a simd::vec3x8 (structure of
 * arrays) and back. Not wrapped.
 *
 * A full batch is six 16-byte loads or stores and five or six in-lane
 * shuffles with AVX (points 0-3 in the low 128-bit halves, 4-7 in the high
 * ones: lane-crossing permutes cost several times more, and with two arrays
 * read and five written per batch they were a fifth of the radiance loop's
 * time), or three 32-byte ones and a fixed shuffle without. The last,
 * partial batch of a range goes lane by lane, repeating its last point in
 * the unused lanes (so they hold ordinary values) and storing only the lanes
 * that exist.
 */

#include "shadelab/SIMDVec3x8.h"

#include <cstring>

#ifdef __AVX__
#include <immintrin.h>
#endif

namespace shadelab
{

/// Points first ... first + count - 1 (count in 1 ... 8).
struct BatchRange
{
  long long first;
  int count;
};

namespace batchio
{
using simd::v8sf;
using simd::v8si;

/// Lanes of two 8-float vectors: index i < 8 is lane i of @p a, 8 + i lane i of @p b.
inline v8sf pick(v8sf a, v8sf b, v8si index)
{
  return __builtin_shuffle(a, b, index);
}
} // namespace batchio

/// Tuples batch.first ... of @p a as one vec3x8 (inline: it belongs in the loop).
inline simd::vec3x8 loadBatch(const float* a, BatchRange batch)
{
  using namespace batchio;
  const float* p = a + 3 * batch.first;
#ifdef __AVX__
  if (batch.count == 8)
  {
    // Points 0-3 in the low 128-bit lanes, 4-7 in the high ones; then the
    // 4-point transpose within each lane (in-lane shuffles only: each is one
    // cheap instruction, where lane-crossing permutes are slow).
    const __m256 m03 = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(p)), _mm_loadu_ps(p + 12), 1);
    const __m256 m14 = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(p + 4)), _mm_loadu_ps(p + 16), 1);
    const __m256 m25 = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(p + 8)), _mm_loadu_ps(p + 20), 1);
    // m03 = x0 y0 z0 x1, m14 = y1 z1 x2 y2, m25 = z2 x3 y3 z3 (per lane)
    const __m256 xy = _mm256_shuffle_ps(m14, m25, _MM_SHUFFLE(2, 1, 3, 2)); // x2 y2 x3 y3
    const __m256 yz = _mm256_shuffle_ps(m03, m14, _MM_SHUFFLE(1, 0, 2, 1)); // y0 z0 y1 z1
    return simd::vec3x8(simd::vfloat8(_mm256_shuffle_ps(m03, xy, _MM_SHUFFLE(2, 0, 3, 0))),
      simd::vfloat8(_mm256_shuffle_ps(yz, xy, _MM_SHUFFLE(3, 1, 2, 0))),
      simd::vfloat8(_mm256_shuffle_ps(yz, m25, _MM_SHUFFLE(3, 0, 3, 1))));
  }
#endif
  v8sf part[3];
  if (batch.count == 8)
  {
    std::memcpy(part, p, sizeof part);
  }
  else
  {
    float values[24];
    for (int i = 0; i < 8; ++i)
    {
      const int from = i < batch.count ? i : batch.count - 1;
      for (int c = 0; c < 3; ++c)
      {
        values[3 * i + c] = p[3 * from + c];
      }
    }
    std::memcpy(part, values, sizeof part);
  }
  // part 0 = x0 y0 z0 x1 y1 z1 x2 y2, part 1 = z2 x3 y3 z3 x4 y4 z4 x5,
  // part 2 = y5 z5 x6 y6 z6 x7 y7 z7. First gather what parts 0 and 1 hold
  // of a component, then the rest from part 2.
  const v8sf x01 = pick(part[0], part[1], v8si{ 0, 3, 6, 9, 12, 15, 0, 0 });
  const v8sf y01 = pick(part[0], part[1], v8si{ 1, 4, 7, 10, 13, 0, 0, 0 });
  const v8sf z01 = pick(part[0], part[1], v8si{ 2, 5, 8, 11, 14, 0, 0, 0 });
  return simd::vec3x8(simd::vfloat8(pick(x01, part[2], v8si{ 0, 1, 2, 3, 4, 5, 10, 13 })),
    simd::vfloat8(pick(y01, part[2], v8si{ 0, 1, 2, 3, 4, 8, 11, 14 })),
    simd::vfloat8(pick(z01, part[2], v8si{ 0, 1, 2, 3, 4, 9, 12, 15 })));
}

/// Writes the batch's lanes of @p v as tuples batch.first ... of @p a.
inline void storeBatch(float* a, BatchRange batch, const simd::vec3x8& v)
{
  using namespace batchio;
#ifdef __AVX__
  if (batch.count == 8)
  {
    // The inverse of the AVX load: within each 128-bit lane, 4 points' x,
    // y, z back to x y z x | y z x y | z x y z, then the low lanes to points
    // 0-3 and the high lanes to points 4-7.
    const __m256 x = v.x.v, y = v.y.v, z = v.z.v;
    const __m256 xy = _mm256_shuffle_ps(x, y, _MM_SHUFFLE(2, 0, 2, 0)); // x0 x2 y0 y2
    const __m256 yz = _mm256_shuffle_ps(y, z, _MM_SHUFFLE(3, 1, 3, 1)); // y1 y3 z1 z3
    const __m256 zx = _mm256_shuffle_ps(z, x, _MM_SHUFFLE(3, 1, 2, 0)); // z0 z2 x1 x3
    const __m256 m03 = _mm256_shuffle_ps(xy, zx, _MM_SHUFFLE(2, 0, 2, 0)); // x0 y0 z0 x1
    const __m256 m14 = _mm256_shuffle_ps(yz, xy, _MM_SHUFFLE(3, 1, 2, 0)); // y1 z1 x2 y2
    const __m256 m25 = _mm256_shuffle_ps(zx, yz, _MM_SHUFFLE(3, 1, 3, 1)); // z2 x3 y3 z3
    float* p = a + 3 * batch.first;
    _mm_storeu_ps(p, _mm256_castps256_ps128(m03));
    _mm_storeu_ps(p + 4, _mm256_castps256_ps128(m14));
    _mm_storeu_ps(p + 8, _mm256_castps256_ps128(m25));
    _mm_storeu_ps(p + 12, _mm256_extractf128_ps(m03, 1));
    _mm_storeu_ps(p + 16, _mm256_extractf128_ps(m14, 1));
    _mm_storeu_ps(p + 20, _mm256_extractf128_ps(m25, 1));
    return;
  }
#endif
  // The inverse of loadBatch: x and y first, then z into its places.
  const v8sf xy0 = pick(v.x.v, v.y.v, v8si{ 0, 8, 0, 1, 9, 0, 2, 10 });
  const v8sf xy1 = pick(v.x.v, v.y.v, v8si{ 0, 3, 11, 0, 4, 12, 0, 5 });
  const v8sf xy2 = pick(v.x.v, v.y.v, v8si{ 13, 0, 6, 14, 0, 7, 15, 0 });
  const v8sf part[3] = { pick(xy0, v.z.v, v8si{ 0, 1, 8, 3, 4, 9, 6, 7 }),
    pick(xy1, v.z.v, v8si{ 10, 1, 2, 11, 4, 5, 12, 7 }), pick(xy2, v.z.v, v8si{ 0, 13, 2, 3, 14, 5, 6, 15 }) };
  float* p = a + 3 * batch.first;
  if (batch.count == 8)
  {
    std::memcpy(p, part, sizeof part);
    return;
  }
  std::memcpy(p, part, sizeof(float) * 3 * static_cast<size_t>(batch.count));
}

} // namespace shadelab

#endif
