#ifndef shadelab_HugePages_h
#define shadelab_HugePages_h
/**
 * @file HugePages.h
 * @brief Large blocks of memory on transparent huge pages, mapped before use.
 *
 * A freshly allocated block of many megabytes is not memory yet: the kernel
 * maps it at the first write of every 4 KiB page, and for a pass that writes
 * each value once those page faults can cost as much CPU time as the pass
 * itself. A block from allocateHugePages() lies on 2 MiB boundaries, is
 * advised for transparent huge pages (madvise(MADV_HUGEPAGE), honoured when
 * /sys/kernel/mm/transparent_hugepage/enabled is "madvise" or "always") and
 * is mapped before it is returned (MADV_POPULATE_WRITE, Linux 5.14 and
 * later), in one call on one thread: left to a parallel pass, two threads
 * writing near each other fault on the same huge page at once, and both
 * allocate and clear 2 MiB, one of them for nothing.
 *
 * Both madvise() calls are advice: without huge pages, or on older kernels,
 * the block is ordinary memory mapped at first write.
 */

#include <cstddef>

namespace shadelab
{

/// The huge-page size on x86-64 and AArch64 Linux with 4 KiB base pages.
constexpr size_t kHugePageBytes = size_t(2) << 20;

/// At least @p bytes (rounded up to a multiple of kHugePageBytes, written to
/// @p capacity when given), uninitialised, for free(); null if the system
/// has no memory to give.
void* allocateHugePages(size_t bytes, size_t* capacity = nullptr);

} // namespace shadelab

#endif
