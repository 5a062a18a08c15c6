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
 */
#include <string>

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

  /// Reads the machine and measures the bandwidth (about a second).
  static BenchMachine measure();
  /// Prints a few lines describing it.
  void print() const;
};

#endif
