#ifndef BenchThreadPlacement_h
#define BenchThreadPlacement_h
/**
 * @brief Where vtkSMPTools' threads may run: each on a CPU of its own, or
 *        anywhere the process may. The benches' machine line measures the
 *        second thread's start both ways, side by side (BenchMachine).
 *
 * Why: a scheduler may put a thread it wakes on the CPU of the thread that
 * woke it, even with another CPU idle, as a virtual machine's kernel that
 * packs work onto few virtual CPUs does (docs/normals.md). A parallel
 * loop's second thread then waits behind the first until the first's time
 * slice ends. Restricted to a CPU of its own, it starts there at once; the
 * difference between the two measurements is what the placement costs.
 *
 * Not a setting of ShadeLab's filters: a pinned thread cannot move away
 * from a CPU another busy process holds, and a process started from a
 * pinned thread inherits its single CPU.
 */

/// Restricts each thread of vtkSMPTools' pool, the calling thread included,
/// to one of the CPUs the process could run on when first called, in the
/// order the threads join (@p pinned), or lets each run on all of those
/// CPUs again (not @p pinned). Returns the number of threads placed: the
/// pool's size, or fewer if a thread did not join within 100 ms (it is then
/// left as it was); 0 with one thread or when the system refuses.
int placeSMPThreads(bool pinned);

#endif
