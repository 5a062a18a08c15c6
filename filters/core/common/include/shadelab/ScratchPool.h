#ifndef shadelab_ScratchPool_h
#define shadelab_ScratchPool_h
/**
 * @file ScratchPool.h
 * @brief Blocks of scratch memory kept from one computation for the next.
 *
 * A filter that runs again on a mesh of the same size asks for the same
 * scratch arrays again. Freed to the C library, those arrays mostly go back
 * to the kernel (glibc trims its heap once the free memory at its top
 * exceeds its trim threshold), and the next run takes a page fault, and the
 * clearing of a page, at every 4 KiB it writes: on the normals filter with
 * splitting, over a quarter of its time at 0.1M-0.5M triangles. A pool
 * keeps the blocks it handed out, up to a byte limit, and hands them out
 * again.
 *
 * Blocks of kHugePageBytes or more come from allocateHugePages()
 * (HugePages.h). They are kept only when released with LargeBlocks::Keep,
 * which a computation asks for where the block outlives every allocation
 * of its run: kept elsewhere, a block would sit idle beside memory the run
 * allocates later (its output, say) and raise its peak memory. A large
 * block freed does not cost just a fault per 2 MiB when allocated again: on
 * a virtual machine that returns freed guest memory to its host (free page
 * reporting, as on ShadeLab's CI machines), a huge page freed a second or
 * more earlier is mapped again at 0.4-1.4 GB/s instead of about 20. So that
 * kept large blocks never sit beside new ones either, a large request that
 * no kept block fits frees the kept large blocks before it allocates.
 * Small blocks are rounded up to 64 KiB, so that a run on a slightly
 * different mesh still finds them.
 *
 * acquire() and release() may be called from any thread. Every block must
 * be released before the pool is destroyed.
 */

#include <cstddef>
#include <mutex>
#include <vector>

namespace shadelab
{

class ScratchPool
{
public:
  /// How many bytes a pool keeps by default.
  static constexpr size_t kDefaultKeptBytes = size_t(64) << 20;

  /// A pool that keeps at most @p keptBytes of released blocks.
  explicit ScratchPool(size_t keptBytes = kDefaultKeptBytes);
  ~ScratchPool();
  ScratchPool(const ScratchPool&) = delete;
  ScratchPool& operator=(const ScratchPool&) = delete;

  /// A block of memory and its usable size.
  struct Block
  {
    void* data = nullptr;
    size_t capacity = 0;
  };

  /// Whether release() may keep a block of kHugePageBytes or more.
  enum class LargeBlocks
  {
    Free, ///< freed: the block's run may still allocate after releasing it
    Keep  ///< kept: released after the last allocation of its run
  };

  /// At least @p bytes, 64-byte aligned, uninitialised: the smallest kept
  /// block that fits, else a new block (for @p bytes of kHugePageBytes or
  /// more, after freeing the kept large blocks). Throws std::bad_alloc.
  Block acquire(size_t bytes);

  /// Takes back a block from acquire(): kept if it is under
  /// kHugePageBytes, or @p large says Keep, and the kept blocks stay within
  /// the limit; else freed.
  void release(Block block, LargeBlocks large = LargeBlocks::Free) noexcept;

  /// Frees the kept blocks of kHugePageBytes or more: called before a run
  /// allocates memory that such a block, kept idle, would sit beside.
  void freeLargeBlocks() noexcept;

  /// Frees every kept block.
  void trim() noexcept;

  /// Bytes in kept blocks.
  size_t keptBytes() const;

  /// Overwrites every kept block with @p byte, so that a test can show that
  /// no computation reads scratch memory it has not written first.
  void fillKept(unsigned char byte);

private:
  mutable std::mutex Mutex;
  std::vector<Block> Kept;
  size_t KeptTotal = 0;
  size_t Limit;
};

} // namespace shadelab

#endif
