#ifndef slNormalsParallel_h
#define slNormalsParallel_h
/**
 * @file slNormalsParallel.h
 * @brief The VTK-free normal algorithms' view of a polygon list and of a
 * parallel loop. Geometry core (ShadeLab::GeometryCore).
 *
 * The algorithms in slFaceNormalsCore.h, slVertexNormalsCore.h,
 * slOrientationCore.h and slFeatureSplitCore.h take no VTK type: polygons are
 * offsets + connectivity (VTK 9's own layout, 32- or 64-bit ids), points are
 * packed xyz of float or double, and parallel loops go through slParallel,
 * which the VTK wrappers fill in with vtkSMPTools. Scratch arrays come from
 * the pool a Parallel names (ScratchArray), so a filter that runs again
 * reuses its memory.
 */

#include "shadelab/ScratchPool.h"

#include <cstdint>
#include <functional>
#include <new>
#include <type_traits>
#include <utility>

namespace slnormals
{

/// A parallel "for" over [begin, end): calls body(b, e) on sub-ranges,
/// possibly concurrently. The default runs serially. @p scratch, when set,
/// is where the algorithms take their scratch arrays (see ScratchArray).
struct Parallel
{
  using Body = std::function<void(int64_t, int64_t)>;
  int threads = 1;
  std::function<void(int64_t begin, int64_t end, int64_t grain, const Body& body)> forRange =
    [](int64_t begin, int64_t end, int64_t, const Body& body) {
      if (begin < end)
      {
        body(begin, end);
      }
    };
  shadelab::ScratchPool* scratch = nullptr;
};

/// A scratch array of values left uninitialised, for passes that overwrite
/// it completely (std::vector would first zero-fill it serially, and take
/// the page faults on one thread). Its memory comes from the pool of the
/// Parallel it is made with, and goes back there, or from the heap when
/// there is no pool. Owns its memory: movable, not copyable.
template <typename T>
class ScratchArray
{
  static_assert(std::is_trivially_copyable<T>::value && std::is_trivially_destructible<T>::value,
    "scratch values are neither constructed nor destroyed");

public:
  using LargeBlocks = shadelab::ScratchPool::LargeBlocks;

  ScratchArray() = default;
  /// @p n values from @p parallel's pool. @p large: whether the pool may
  /// keep the memory when it is large (ScratchPool::release()); Keep only
  /// for an array that outlives every allocation of its computation.
  /// Throws std::bad_alloc.
  ScratchArray(const Parallel& parallel, size_t n, LargeBlocks large = LargeBlocks::Free)
    : Pool(parallel.scratch)
    , Size(n)
    , Large(large)
  {
    if (n && this->Pool)
    {
      this->Memory = this->Pool->acquire(n * sizeof(T));
    }
    else if (n)
    {
      this->Memory = { ::operator new(n * sizeof(T)), n * sizeof(T) };
    }
  }
  ScratchArray(ScratchArray&& other) noexcept { this->swap(other); }
  ScratchArray& operator=(ScratchArray&& other) noexcept
  {
    ScratchArray(std::move(other)).swap(*this);
    return *this;
  }
  ScratchArray(const ScratchArray&) = delete;
  ScratchArray& operator=(const ScratchArray&) = delete;
  ~ScratchArray() { this->reset(); }

  /// Gives the memory back; the array is then empty.
  void reset() noexcept
  {
    if (this->Pool)
    {
      this->Pool->release(this->Memory, this->Large);
    }
    else
    {
      ::operator delete(this->Memory.data);
    }
    this->Memory = {};
    this->Size = 0;
  }

  T* data() const { return static_cast<T*>(this->Memory.data); }
  size_t size() const { return this->Size; }
  bool empty() const { return this->Size == 0; }
  T& operator[](size_t i) const { return this->data()[i]; }
  T* begin() const { return this->data(); }
  T* end() const { return this->data() + this->Size; }

private:
  void swap(ScratchArray& other) noexcept
  {
    std::swap(this->Pool, other.Pool);
    std::swap(this->Memory, other.Memory);
    std::swap(this->Size, other.Size);
    std::swap(this->Large, other.Large);
  }

  shadelab::ScratchPool* Pool = nullptr;
  shadelab::ScratchPool::Block Memory;
  size_t Size = 0;
  LargeBlocks Large = LargeBlocks::Free;
};

/// Polygons as VTK 9 stores them: polygon f has the point ids
/// connectivity[offsets[f]] .. connectivity[offsets[f+1]-1].
template <typename Id>
struct Polygons
{
  const Id* offsets = nullptr; ///< numPolygons + 1 entries
  Id* connectivity = nullptr;  ///< mutable only for orientation flips
  int64_t numPolygons = 0;

  int64_t begin(int64_t f) const { return static_cast<int64_t>(offsets[f]); }
  int64_t end(int64_t f) const { return static_cast<int64_t>(offsets[f + 1]); }
  int64_t size(int64_t f) const { return end(f) - begin(f); }
};

} // namespace slnormals

#endif
