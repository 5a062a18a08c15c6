#ifndef shadelab_ThreadSpread_h
#define shadelab_ThreadSpread_h
/**
 * @file ThreadSpread.h
 * @brief Keeps the threads of one parallel loop on different CPUs, without
 * pinning any of them.
 *
 * Some kernels (the 2-CPU KVM guests ShadeLab's CI runs on, whose command
 * line has `sched_vcpu_pack`) wake a sleeping thread-pool worker on the CPU
 * of the thread that woke it, even with another CPU idle. The worker then
 * waits there until the caller's time slice ends (about 1.8 ms measured),
 * or shares that CPU with it, and a loop that two threads should run in
 * half the time takes as long as on one.
 *
 * A ThreadSpread is made by the thread that starts a loop, and enter() is
 * called at the start of every chunk of the loop, by whichever thread runs
 * it. The starting thread yields its CPU once, at its first chunk, so that
 * a worker woken onto that CPU runs at once, if no loop ended in the last
 * millisecond: only then are the pool's workers asleep (TBB's worker joins
 * within about 30 us after 1 ms without work and misses most loops after
 * 10 ms, as shadelab_bench_machine measures), and yielding in every loop of
 * an update would hand the CPU to other busy processes for nothing. A worker
 * that finds itself on the starting thread's CPU moves itself to another
 * CPU it is allowed on (its affinity is narrowed to exclude that CPU, which
 * migrates it, and set back straight away). No thread stays pinned: a
 * pinned thread could not leave a CPU that another process keeps busy, and
 * a process it started would inherit the single CPU.
 *
 * Caveats: Linux only (elsewhere enter() does nothing); a thread whose
 * affinity allows one CPU is left where it is.
 */

#include <atomic>
#include <thread>

namespace shadelab
{

class ThreadSpread
{
public:
  /// Made by the thread that then starts the loop (its "caller").
  ThreadSpread();
  /// Notes when the loop ended (see willYield()).
  ~ThreadSpread();
  ThreadSpread(const ThreadSpread&) = delete;
  ThreadSpread& operator=(const ThreadSpread&) = delete;

  /// Called first thing in every chunk of the loop, by the thread that runs
  /// it. Returns whether it moved the thread to another CPU.
  bool enter();

  /// Whether the starting thread is still to yield at its first chunk: true
  /// when no ThreadSpread ended in the millisecond before this one was made.
  bool willYield() const { return !this->CallerYielded.load(std::memory_order_relaxed); }

  /// Moves the calling thread off CPU @p cpu if its affinity allows another
  /// CPU, and restores its affinity. Returns whether it moved.
  static bool moveOff(int cpu);

private:
  std::thread::id Caller;
  std::atomic<int> CallerCpu{ -1 };
  std::atomic<bool> CallerYielded{ false };
};

} // namespace shadelab

#endif
