#ifndef shadelab_bench_BenchMemory_h
#define shadelab_bench_BenchMemory_h
// Peak resident memory of a job, Linux only: the job runs in a forked child
// whose high-water mark (VmHWM) is reset after the input is built.

#include <functional>

/// Runs @p job in a child process; returns the child's peak resident memory
/// above its resident memory before the job, in bytes (-1 on failure).
long long slPeakMemoryAbove(const std::function<void()>& job);

#endif
