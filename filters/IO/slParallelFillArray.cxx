#include "slParallelFillArray.h"

#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace shadelab
{

namespace
{
/// The huge-page size on x86-64 and AArch64 Linux with 4 KiB base pages.
constexpr size_t kHugePage = size_t(2) << 20;
} // namespace

vtkSmartPointer<vtkFloatArray> newParallelFillArray(const std::string& name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name.c_str());
  array->SetNumberOfComponents(components);
  const vtkIdType values = static_cast<vtkIdType>(components) * tuples;
  const size_t bytes = static_cast<size_t>(values) * sizeof(float);
  if (bytes < kHugePage)
  {
    // Small arrays gain nothing from huge pages.
    array->SetNumberOfTuples(tuples);
    return array;
  }
  // aligned_alloc needs a size that is a multiple of the alignment.
  const size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  void* memory = std::aligned_alloc(kHugePage, rounded);
  if (!memory)
  {
    // Let VTK try (and report the failure its usual way).
    array->SetNumberOfTuples(tuples);
    return array;
  }
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Advice only: if the kernel has no huge page to give, it maps 4 KiB pages.
  madvise(memory, rounded, MADV_HUGEPAGE);
#endif
  array->SetArray(static_cast<float*>(memory), values, 0, vtkAbstractArray::VTK_DATA_ARRAY_FREE);
  return array;
}

} // namespace shadelab
