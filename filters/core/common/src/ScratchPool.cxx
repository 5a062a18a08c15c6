#include "shadelab/ScratchPool.h"

#include "shadelab/HugePages.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <new>

namespace shadelab
{

namespace
{
constexpr size_t kGranule = size_t(64) << 10;

ScratchPool::Block allocate(size_t bytes)
{
  ScratchPool::Block b;
  if (bytes >= kHugePageBytes)
  {
    b.data = allocateHugePages(bytes, &b.capacity);
  }
  else
  {
    b.capacity = (bytes + kGranule - 1) / kGranule * kGranule;
    b.data = std::aligned_alloc(64, b.capacity);
  }
  if (!b.data)
  {
    throw std::bad_alloc();
  }
  return b;
}
} // namespace

ScratchPool::ScratchPool(size_t keptBytes)
  : Limit(keptBytes)
{
}

ScratchPool::~ScratchPool()
{
  this->trim();
}

ScratchPool::Block ScratchPool::acquire(size_t bytes)
{
  bytes = bytes ? bytes : 1;
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    // The smallest kept block that fits. A run that repeats the last one
    // finds the blocks it had; a run that differs still reuses what it can
    // rather than add new memory beside idle blocks.
    size_t best = this->Kept.size();
    for (size_t i = 0; i < this->Kept.size(); ++i)
    {
      const size_t c = this->Kept[i].capacity;
      if (c >= bytes && (best == this->Kept.size() || c < this->Kept[best].capacity))
      {
        best = i;
      }
    }
    if (best < this->Kept.size())
    {
      const Block b = this->Kept[best];
      this->Kept[best] = this->Kept.back();
      this->Kept.pop_back();
      this->KeptTotal -= b.capacity;
      return b;
    }
  }
  if (bytes >= kHugePageBytes)
  {
    // None fits: the kept large blocks would only sit beside the new one.
    this->freeLargeBlocks();
  }
  return allocate(bytes);
}

void ScratchPool::release(Block block, LargeBlocks large) noexcept
{
  if (!block.data)
  {
    return;
  }
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    const bool keepable = block.capacity < kHugePageBytes || large == LargeBlocks::Keep;
    if (keepable && this->KeptTotal + block.capacity <= this->Limit)
    {
      try
      {
        this->Kept.push_back(block);
        this->KeptTotal += block.capacity;
        return;
      }
      catch (const std::bad_alloc&)
      {
        // No room to remember it: free it below.
      }
    }
  }
  std::free(block.data);
}

void ScratchPool::freeLargeBlocks() noexcept
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  const auto large = std::partition(
    this->Kept.begin(), this->Kept.end(), [](const Block& b) { return b.capacity < kHugePageBytes; });
  for (auto b = large; b != this->Kept.end(); ++b)
  {
    this->KeptTotal -= b->capacity;
    std::free(b->data);
  }
  this->Kept.erase(large, this->Kept.end());
}

void ScratchPool::trim() noexcept
{
  std::vector<Block> kept;
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    kept.swap(this->Kept);
    this->KeptTotal = 0;
  }
  for (const Block& b : kept)
  {
    std::free(b.data);
  }
}

size_t ScratchPool::keptBytes() const
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  return this->KeptTotal;
}

void ScratchPool::fillKept(unsigned char byte)
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  for (const Block& b : this->Kept)
  {
    std::memset(b.data, byte, b.capacity);
  }
}

} // namespace shadelab
