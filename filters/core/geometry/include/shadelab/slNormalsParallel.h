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
 * which the VTK wrappers fill in with vtkSMPTools.
 */

#include <cstdint>
#include <functional>
#include <memory>

namespace slnormals
{

/// A parallel "for" over [begin, end): calls body(b, e) on sub-ranges,
/// possibly concurrently. The default runs serially.
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
};

/// An array of @p n values left uninitialised, for scratch arrays that a
/// parallel pass overwrites completely: std::vector would first zero-fill
/// them serially (and take the page faults on one thread).
template <typename T>
std::unique_ptr<T[]> uninitialisedArray(size_t n)
{
  return std::unique_ptr<T[]>(new T[n]);
}

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
