// placeSMPThreads(): pinned, each of vtkSMPTools' threads is allowed on one
// CPU, a different one per thread; freed, on all of them again. Each test
// runs in a process of its own (gtest_discover_tests) and frees the threads
// when it ends, so pinning in one cannot leak into another.
#include "BenchThreadPlacement.h"

#include <vtkSMPTools.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include <sched.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace
{
/// The CPUs the calling thread may run on.
std::set<int> allowedHere()
{
  cpu_set_t set;
  std::set<int> cpus;
  if (sched_getaffinity(0, sizeof(set), &set) == 0) // 0: the calling thread
  {
    for (int c = 0; c < CPU_SETSIZE; ++c)
    {
      if (CPU_ISSET(c, &set))
      {
        cpus.insert(c);
      }
    }
  }
  return cpus;
}

/// Each pool thread's allowed CPUs, by kernel thread id, from a loop of two
/// tasks that both wait until two threads run them (so both threads do).
std::map<long, std::set<int>> allowedPerPoolThread()
{
  std::mutex m;
  std::map<long, std::set<int>> seen;
  std::atomic<int> started{ 0 };
  const auto giveUp = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  vtkSMPTools::For(0, 2, 1, [&](vtkIdType, vtkIdType) {
    ++started;
    while (started.load() < 2 && std::chrono::steady_clock::now() < giveUp)
    {
      std::this_thread::yield();
    }
    std::lock_guard<std::mutex> lock(m);
    seen[syscall(SYS_gettid)] = allowedHere();
  });
  return seen;
}

class ThreadPlacement : public ::testing::Test
{
protected:
  void SetUp() override
  {
    if (allowedHere().size() < 2)
    {
      GTEST_SKIP() << "needs two CPUs";
    }
    vtkSMPTools::Initialize(2);
  }
  // So that the tests also pass when run in one process.
  void TearDown() override
  {
    vtkSMPTools::Initialize(2);
    placeSMPThreads(false);
  }
};
} // namespace

TEST_F(ThreadPlacement, EachPoolThreadGetsACpuOfItsOwn)
{
  const std::set<int> before = allowedHere();
  const auto free = allowedPerPoolThread();
  ASSERT_EQ(free.size(), 2u);
  for (const auto& thread : free)
  {
    EXPECT_EQ(thread.second, before) << "a thread was pinned before placeSMPThreads()";
  }

  EXPECT_EQ(placeSMPThreads(true), 2);
  const auto pinned = allowedPerPoolThread();
  ASSERT_EQ(pinned.size(), 2u);
  std::set<int> used;
  for (const auto& thread : pinned)
  {
    ASSERT_EQ(thread.second.size(), 1u) << "thread " << thread.first;
    EXPECT_EQ(before.count(*thread.second.begin()), 1u) << "a CPU the process was not allowed on";
    used.insert(*thread.second.begin());
  }
  EXPECT_EQ(used.size(), 2u) << "both threads on one CPU";
}

TEST_F(ThreadPlacement, FreedThreadsMayRunAnywhereAgain)
{
  const std::set<int> before = allowedHere();
  ASSERT_EQ(placeSMPThreads(true), 2);
  EXPECT_EQ(placeSMPThreads(false), 2);
  const auto freed = allowedPerPoolThread();
  ASSERT_EQ(freed.size(), 2u);
  for (const auto& thread : freed)
  {
    EXPECT_EQ(thread.second, before) << "thread " << thread.first;
  }
}

TEST_F(ThreadPlacement, NothingToPlaceOnOneThread)
{
  vtkSMPTools::Initialize(1);
  EXPECT_EQ(placeSMPThreads(true), 0);
  EXPECT_GE(allowedHere().size(), 2u);
}
