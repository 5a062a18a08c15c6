#include "BenchThreadPlacement.h"

#include <vtkSMPTools.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

#include <pthread.h>
#include <sched.h>

namespace
{
/// The CPUs the process may run on, read once: once pinned, the calling
/// thread's own mask names a single CPU.
const cpu_set_t& allowedCpus()
{
  static const cpu_set_t allowed = [] {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof(set), &set) != 0)
    {
      CPU_ZERO(&set);
    }
    return set;
  }();
  return allowed;
}

/// The @p k-th allowed CPU, counting round robin.
int nthAllowedCpu(int k)
{
  const cpu_set_t& allowed = allowedCpus();
  std::vector<int> cpus;
  for (int c = 0; c < CPU_SETSIZE; ++c)
  {
    if (CPU_ISSET(c, &allowed))
    {
      cpus.push_back(c);
    }
  }
  return cpus[static_cast<size_t>(k) % cpus.size()];
}
} // namespace

int placeSMPThreads(bool pinned)
{
  const int threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  if (threads < 2 || CPU_COUNT(&allowedCpus()) == 0)
  {
    return 0;
  }
  // One task per thread: each task waits until every thread holds one, so
  // that no thread can take two, then the thread places itself. A woken
  // thread starts within a few milliseconds even where the scheduler packs
  // threads; the limit only matters when a thread cannot join at all, as in
  // a loop nested in another that holds the other threads. A thread that
  // then runs a second task is counted once.
  std::atomic<int> joined{ 0 };
  std::mutex seen;
  std::vector<std::thread::id> placed;
  const auto giveUp = std::chrono::steady_clock::now() + std::chrono::milliseconds(100);
  vtkSMPTools::For(0, threads, 1, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType t = begin; t < end; ++t)
    {
      const int order = joined++;
      while (joined.load() < threads && std::chrono::steady_clock::now() < giveUp)
      {
        std::this_thread::yield();
      }
      cpu_set_t set = allowedCpus();
      if (pinned)
      {
        CPU_ZERO(&set);
        CPU_SET(nthAllowedCpu(order), &set);
      }
      if (pthread_setaffinity_np(pthread_self(), sizeof(set), &set) == 0)
      {
        std::lock_guard<std::mutex> lock(seen);
        if (std::find(placed.begin(), placed.end(), std::this_thread::get_id()) == placed.end())
        {
          placed.push_back(std::this_thread::get_id());
        }
      }
    }
  });
  return static_cast<int>(placed.size());
}
