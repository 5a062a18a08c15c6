// The order of jobs in a bench's rounds (bench/common/BenchTiming.h): every
// round runs every job once, and over a cycle of rounds every job comes
// right after every other job equally often, counted here pair by pair.

#include "BenchTiming.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <utility>

TEST(RoundOrder, EveryRoundRunsEveryJobOnce)
{
  for (size_t n = 1; n <= 9; ++n)
  {
    for (int round = 0; round < 20; ++round)
    {
      std::vector<size_t> order = roundOrder(n, round);
      std::sort(order.begin(), order.end());
      std::vector<size_t> all(n);
      std::iota(all.begin(), all.end(), size_t(0));
      EXPECT_EQ(order, all) << n << " jobs, round " << round;
    }
  }
  EXPECT_TRUE(roundOrder(0, 3).empty());
}

TEST(RoundOrder, EveryJobFollowsEveryOtherEquallyOftenInACycle)
{
  for (size_t n = 2; n <= 9; ++n)
  {
    const int cycle = static_cast<int>(n % 2 ? 2 * n : n);
    std::map<std::pair<size_t, size_t>, int> follows;
    for (int round = 0; round < cycle; ++round)
    {
      const std::vector<size_t> order = roundOrder(n, round);
      for (size_t k = 1; k < order.size(); ++k)
      {
        ++follows[{ order[k - 1], order[k] }];
      }
    }
    // n (n - 1) ordered pairs of different jobs, each seen as often.
    EXPECT_EQ(follows.size(), n * (n - 1)) << n << " jobs";
    for (const auto& pair : follows)
    {
      EXPECT_EQ(pair.second, n % 2 ? 2 : 1) << n << " jobs: " << pair.first.second << " after " << pair.first.first;
    }
  }
}

TEST(RoundOrder, NoJobAlwaysFollowsTheSameOneInAShortRun)
{
  // The normals bench: six jobs, five rounds. Each job that is not first in
  // a round has a different job before it in every round.
  for (size_t job = 0; job < 6; ++job)
  {
    std::map<size_t, int> before;
    for (int round = 0; round < 5; ++round)
    {
      const std::vector<size_t> order = roundOrder(6, round);
      const size_t k = static_cast<size_t>(std::find(order.begin(), order.end(), job) - order.begin());
      if (k > 0)
      {
        ++before[order[k - 1]];
      }
    }
    for (const auto& b : before)
    {
      EXPECT_EQ(b.second, 1) << "job " << job << " follows job " << b.first << " in " << b.second << " rounds";
    }
  }
}

TEST(RoundOrder, RoundsRepeatAfterACycle)
{
  EXPECT_EQ(roundOrder(6, 6), roundOrder(6, 0));
  EXPECT_EQ(roundOrder(5, 10), roundOrder(5, 0));
  EXPECT_NE(roundOrder(5, 5), roundOrder(5, 0));
}
