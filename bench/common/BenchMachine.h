#ifndef BenchMachine_h
#define BenchMachine_h
/**
 * @brief The machine a bench ran on, printed at the top of its output so
 *        that every figure comes with it: CPU model, logical cores, the
 *        threads and SMP backend in use, memory, the load average, and the
 *        memory bandwidth measured in the same run.
 *
 * The bandwidth is the best of 5 copies of a 256 MiB buffer into another
 * (bytes read + bytes written per second), once on one thread and once on
 * the threads vtkSMPTools uses: the floor a pass over large arrays cannot
 * beat, against which a filter's bytes moved per second can be judged.
 *
 * With more than one thread it also measures how soon a second thread
 * joins a parallel loop after the pool had no work (WakeUp): on a virtual
 * machine that can take longer than a small mesh's whole update, which
 * bounds what a second thread can give there. It measures that once more
 * with each thread pinned to a CPU of its own (BenchThreadPlacement.h), then
 * frees the threads again: the difference is the cost of where the
 * scheduler puts a woken thread, not of waking it.
 */
#include <string>

/// How soon a second thread joins a vtkSMPTools::For of two tasks of 200
/// microseconds each, started after the pool was idle for a while.
struct WakeUp
{
  int idleMilliseconds = 0; ///< the pool's idle time before each loop
  int tries = 0;
  int missed = 0; ///< loops whose two tasks both ran on the calling thread
  /// When the second thread started its task, median over the loops; a
  /// missed loop counts as later than any other (HUGE_VAL if half or more missed).
  double medianMicroseconds = 0;
};

struct BenchMachine
{
  std::string cpuModel;
  int logicalCores = 0;
  int threads = 0;
  std::string smpBackend;
  double memoryGiB = 0;
  double bandwidthOneThread = 0;   ///< GB/s (1e9 bytes per second)
  double bandwidthAllThreads = 0;  ///< GB/s
  std::string loadAverage;         ///< /proc/loadavg's first three fields
  WakeUp wakeUpShort, wakeUpLong;  ///< after 1 ms and 10 ms idle; tries 0 on one thread
  WakeUp wakeUpLongPinned;         ///< after 10 ms idle, threads pinned; tries 0 if they could not be

  /// Reads the machine and measures the bandwidth and the wake-ups (about
  /// two seconds).
  static BenchMachine measure();
  /// Prints a few lines describing it.
  void print() const;
};

#endif
