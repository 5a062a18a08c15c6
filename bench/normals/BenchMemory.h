#ifndef shadelab_bench_BenchMemory_h
#define shadelab_bench_BenchMemory_h
// Peak resident memory of a job, Linux only: the process's high-water mark
// (VmHWM) is reset to its resident size just before the job runs.

#include <functional>

/// Runs @p job in this process; returns the peak resident memory during the
/// job above the resident memory just before it, in bytes (-1 on failure).
///
/// Freed heap memory is first handed back to the system (malloc_trim), so
/// the job cannot reuse pages the count would not see. The job runs in the
/// process itself, not in a forked child: a child of a process whose thread
/// pool is running may inherit a lock held by a thread that does not exist
/// in it, and wait forever. What the process did before still shows (memory
/// the allocator kept, or did not): the normals bench therefore calls this
/// in a new process per job, started with exec (NormalsBench.cxx,
/// memoryInNewProcesses).
long long slPeakMemoryAbove(const std::function<void()>& job);

#endif
