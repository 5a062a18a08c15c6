#ifndef slBatchIO_h
#define slBatchIO_h
/**
 * @file slBatchIO.h
 * @brief Internal: moves 8 consecutive xyz tuples of a flat float array
 * (VTK's layout, array of structures) into a simd::vec3x8 (structure of
 * arrays) and back. Not wrapped.
 *
 * A full batch is three 32-byte loads or stores and a fixed shuffle; the
 * last, partial batch of a range goes lane by lane, repeating its last point
 * in the unused lanes (so they hold ordinary values) and storing only the
 * lanes that exist.
 */

#include "shadelab/SIMDVec3x8.h"

#include <cstring>

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
