#include "shadelab/ThreadSpread.h"

#ifdef __linux__
#include <sched.h>
#endif

#include <chrono>
#include <cstdint>
#include <limits>

namespace shadelab
{

namespace
{
/// Steady-clock nanoseconds.
int64_t now()
{
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
    .count();
}

/// When the last loop of any ThreadSpread ended (steady-clock ns); at first
/// long ago, so that the first loop yields.
std::atomic<int64_t> lastLoopEnd{ std::numeric_limits<int64_t>::min() / 2 };

/// After this long without a loop the pool's workers are taken to be asleep.
constexpr int64_t kWorkersAsleepAfterNs = 1000000;
} // namespace

ThreadSpread::ThreadSpread()
  : Caller(std::this_thread::get_id())
  , CallerYielded(now() - lastLoopEnd.load(std::memory_order_relaxed) < kWorkersAsleepAfterNs)
{
#ifdef __linux__
  this->CallerCpu.store(sched_getcpu(), std::memory_order_relaxed);
#endif
}

ThreadSpread::~ThreadSpread()
{
  lastLoopEnd.store(now(), std::memory_order_relaxed);
}

bool ThreadSpread::enter()
{
#ifdef __linux__
  const int cpu = sched_getcpu();
  if (std::this_thread::get_id() == this->Caller)
  {
    this->CallerCpu.store(cpu, std::memory_order_relaxed);
    // The loop has spawned its tasks and woken the pool by now: a worker
    // placed on this CPU gets it for a moment and moves off (below).
    if (!this->CallerYielded.exchange(true, std::memory_order_relaxed))
    {
      sched_yield();
    }
    return false;
  }
  return cpu >= 0 && cpu == this->CallerCpu.load(std::memory_order_relaxed) && moveOff(cpu);
#else
  return false;
#endif
}

bool ThreadSpread::moveOff(int cpu)
{
#ifdef __linux__
  cpu_set_t allowed;
  if (cpu < 0 || cpu >= CPU_SETSIZE || sched_getaffinity(0, sizeof(allowed), &allowed) != 0 ||
    !CPU_ISSET(cpu, &allowed) || CPU_COUNT(&allowed) < 2)
  {
    return false;
  }
  cpu_set_t others = allowed;
  CPU_CLR(cpu, &others);
  // Narrowing the affinity migrates the thread before the call returns;
  // restoring it leaves the thread where it now runs, free to move again.
  const bool moved = sched_setaffinity(0, sizeof(others), &others) == 0 && sched_getcpu() != cpu;
  sched_setaffinity(0, sizeof(allowed), &allowed);
  return moved;
#else
  (void)cpu;
  return false;
#endif
}

} // namespace shadelab
