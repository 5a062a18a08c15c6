// slAtomicMinimum: the shared "first bad index" of the parallel searches
// ends at the smallest candidate whatever order the candidates come in.
#include "shadelab/slAtomicMinimum.h"

#include <vtkSMPTools.h>
#include <vtkType.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <numeric>
#include <random>
#include <vector>

TEST(AtomicMinimum, KeepsTheSmallestCandidateInAnyOrder)
{
  std::atomic<vtkIdType> first{ 1000 };
  for (vtkIdType candidate : { 500, 700, 20, 999, 21, 1000000 })
  {
    slAtomicMinimum(first, candidate);
  }
  EXPECT_EQ(first.load(), 20); // not the last, not the first candidate

  // Descending, ascending and shuffled candidates from parallel ranges.
  std::vector<vtkIdType> candidates(200000);
  std::iota(candidates.begin(), candidates.end(), vtkIdType(7));
  std::vector<std::vector<vtkIdType>> orders{ candidates, candidates, candidates };
  std::reverse(orders[1].begin(), orders[1].end());
  std::shuffle(orders[2].begin(), orders[2].end(), std::mt19937(3));
  for (const std::vector<vtkIdType>& order : orders)
  {
    std::atomic<vtkIdType> smallest{ vtkIdType(1) << 40 };
    vtkSMPTools::For(0, static_cast<vtkIdType>(order.size()), 1000, [&](vtkIdType b, vtkIdType e) {
      for (vtkIdType i = b; i < e; ++i)
      {
        slAtomicMinimum(smallest, order[static_cast<size_t>(i)]);
      }
    });
    EXPECT_EQ(smallest.load(), 7);
  }
}
