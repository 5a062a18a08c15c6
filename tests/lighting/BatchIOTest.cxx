// slBatchIO.h: the radiance loop's moves between VTK's xyz tuples and 8-lane
// batches, compiled with the loop's instructions (AVX2 on ShadeLab's
// machines), checked value by value against the tuple layout.
#include "slBatchIO.h"

#include <gtest/gtest.h>

#include <vector>

using shadelab::BatchRange;

namespace
{
/// Tuple t of a test array holds (100 t, 100 t + 1, 100 t + 2): every value differs.
std::vector<float> numberedTuples(int tuples)
{
  std::vector<float> a(3 * tuples);
  for (int i = 0; i < 3 * tuples; ++i)
  {
    a[i] = 100.0f * (i / 3) + i % 3;
  }
  return a;
}
} // namespace

TEST(BatchIO, LoadPutsTupleFirstPlusIInLaneI)
{
  const std::vector<float> a = numberedTuples(40);
  for (long long first : { 0, 1, 5, 13, 32 })
  {
    for (int count = 1; count <= 8; ++count)
    {
      const shadelab::simd::vec3x8 v = shadelab::loadBatch(a.data(), BatchRange{ first, count });
      for (int i = 0; i < 8; ++i)
      {
        // Lanes past the batch repeat its last tuple.
        const float t = static_cast<float>(first + (i < count ? i : count - 1));
        EXPECT_EQ(v.x.v[i], 100.0f * t) << first << "+" << i << " of " << count;
        EXPECT_EQ(v.y.v[i], 100.0f * t + 1.0f) << first << "+" << i << " of " << count;
        EXPECT_EQ(v.z.v[i], 100.0f * t + 2.0f) << first << "+" << i << " of " << count;
      }
    }
  }
}

TEST(BatchIO, StoreWritesTheBatchsTuplesAndNothingElse)
{
  const std::vector<float> source = numberedTuples(40);
  for (long long first : { 0, 1, 5, 13, 32 })
  {
    for (int count = 1; count <= 8; ++count)
    {
      std::vector<float> target(source.size(), -1.0f);
      shadelab::storeBatch(target.data(), BatchRange{ first, count },
        shadelab::loadBatch(source.data(), BatchRange{ first, count }));
      for (size_t k = 0; k < target.size(); ++k)
      {
        const long long tuple = static_cast<long long>(k / 3);
        const bool inBatch = tuple >= first && tuple < first + count;
        EXPECT_EQ(target[k], inBatch ? source[k] : -1.0f) << "value " << k << ", batch " << first << "+" << count;
      }
    }
  }
}
