// ThreadSpread: a worker that runs a chunk on the CPU of the loop's caller
// moves to another CPU and keeps its affinity; the caller and a worker
// elsewhere stay where they are. The kernel picks the CPUs, so each test
// first puts the threads where it needs them with a short pinning of its
// own; a thread set free may be moved by the kernel before the call under
// test, so placing and calling is tried again a few times.
#include "shadelab/ThreadSpread.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include <sched.h>

namespace
{
cpu_set_t allowedHere()
{
  cpu_set_t set;
  CPU_ZERO(&set);
  sched_getaffinity(0, sizeof(set), &set);
  return set;
}

/// The first two CPUs the process may use, or false.
bool twoCpus(int& a, int& b)
{
  const cpu_set_t set = allowedHere();
  a = b = -1;
  for (int c = 0; c < CPU_SETSIZE && b < 0; ++c)
  {
    if (CPU_ISSET(c, &set))
    {
      (a < 0 ? a : b) = c;
    }
  }
  return b >= 0;
}

/// Moves the calling thread to @p cpu and lets it go anywhere again (it
/// stays on @p cpu until the kernel moves it).
void placeOn(int cpu, const cpu_set_t& all)
{
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(cpu, &one);
  sched_setaffinity(0, sizeof(one), &one);
  sched_setaffinity(0, sizeof(all), &all);
}

/// Pins the calling thread to @p cpu for the scope.
struct PinnedTo
{
  cpu_set_t all = allowedHere();
  explicit PinnedTo(int cpu)
  {
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(cpu, &one);
    sched_setaffinity(0, sizeof(one), &one);
  }
  ~PinnedTo() { sched_setaffinity(0, sizeof(all), &all); }
};

class ThreadSpreadTest : public ::testing::Test
{
protected:
  int a = -1, b = -1;
  void SetUp() override
  {
    if (!twoCpus(a, b))
    {
      GTEST_SKIP() << "needs two CPUs";
    }
  }
};
} // namespace

TEST_F(ThreadSpreadTest, MoveOffLeavesTheCpuAndKeepsTheAffinity)
{
  const cpu_set_t all = allowedHere();
  bool moved = false;
  for (int attempt = 0; attempt < 50 && !moved; ++attempt)
  {
    placeOn(a, all);
    moved = sched_getcpu() == a && shadelab::ThreadSpread::moveOff(a);
  }
  EXPECT_TRUE(moved);
  const cpu_set_t after = allowedHere();
  EXPECT_TRUE(CPU_EQUAL(&after, &all)) << "the thread was left pinned";
}

TEST_F(ThreadSpreadTest, MoveOffLeavesAThreadWithOneCpuAlone)
{
  PinnedTo pin(a);
  EXPECT_FALSE(shadelab::ThreadSpread::moveOff(a));
  EXPECT_EQ(sched_getcpu(), a);
  const cpu_set_t after = allowedHere();
  EXPECT_EQ(CPU_COUNT(&after), 1) << "the thread's own pinning was undone";
}

TEST_F(ThreadSpreadTest, AWorkerOnTheCallersCpuMovesOff)
{
  PinnedTo caller(a); // the caller runs on CPU a and so records it
  shadelab::ThreadSpread spread;
  const cpu_set_t all = caller.all;
  bool moved = false, pinned = true;
  std::thread worker([&] {
    for (int attempt = 0; attempt < 50 && !moved; ++attempt)
    {
      placeOn(a, all);
      moved = spread.enter();
    }
    const cpu_set_t mine = allowedHere();
    pinned = !CPU_EQUAL(&mine, &all);
  });
  worker.join();
  EXPECT_TRUE(moved);
  EXPECT_FALSE(pinned);
}

TEST_F(ThreadSpreadTest, AWorkerElsewhereAndTheCallerStay)
{
  PinnedTo caller(a);
  shadelab::ThreadSpread spread;
  bool workerMoved = true;
  std::thread worker([&] {
    PinnedTo pin(b); // so the kernel cannot move it onto a meanwhile
    workerMoved = spread.enter();
  });
  worker.join();
  EXPECT_FALSE(workerMoved);
  EXPECT_FALSE(spread.enter()); // the caller: yields once, stays where it was
  EXPECT_FALSE(spread.enter());
  EXPECT_EQ(sched_getcpu(), a);
  const cpu_set_t mine = allowedHere();
  EXPECT_EQ(CPU_COUNT(&mine), 1);
}

TEST(ThreadSpreadYield, TheCallerYieldsOnlyAfterTheWorkersHadAMillisecondIdle)
{
  // Made right after another ended (tried again if this thread was held up
  // for a millisecond in between).
  bool awake = false;
  for (int attempt = 0; attempt < 20 && !awake; ++attempt)
  {
    {
      shadelab::ThreadSpread first;
    }
    shadelab::ThreadSpread rightAfter;
    awake = !rightAfter.willYield();
  }
  EXPECT_TRUE(awake) << "a loop had just ended: the workers are awake";
  std::this_thread::sleep_for(std::chrono::milliseconds(3));
  shadelab::ThreadSpread after_idle;
  EXPECT_TRUE(after_idle.willYield());
  after_idle.enter(); // the caller's first chunk: yields
  EXPECT_FALSE(after_idle.willYield());
}
