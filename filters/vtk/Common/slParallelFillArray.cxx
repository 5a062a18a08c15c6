#include "slParallelFillArray.h"
#include "slCoreBoundary.h"

#include "shadelab/HugePages.h"

namespace shadelab
{

vtkSmartPointer<vtkFloatArray> newParallelFillArray(const std::string& name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name.c_str());
  array->SetNumberOfComponents(components);
  const vtkIdType values = static_cast<vtkIdType>(components) * tuples;
  const size_t bytes = static_cast<size_t>(values) * sizeof(float);
  // Small arrays gain nothing from huge pages.
  void* memory = bytes < kHugePageBytes ? nullptr : allocateHugePages(bytes);
  if (!memory)
  {
    // Small, or no huge pages: VTK allocates (and reports a failure its
    // usual way; then std::bad_alloc, as the caller would fill no storage).
    slSetNumberOfTuplesOrThrow(array, tuples);
    return array;
  }
  array->SetArray(static_cast<float*>(memory), values, 0, vtkAbstractArray::VTK_DATA_ARRAY_FREE);
  return array;
}

vtkSmartPointer<vtkFloatArray> recycleParallelFillArray(
  vtkSmartPointer<vtkDataArray> previous, const std::string& name, int components, vtkIdType tuples)
{
  vtkSmartPointer<vtkFloatArray> array = vtkFloatArray::SafeDownCast(previous);
  previous = nullptr;
  // `array` must hold the only reference: a caller that kept its own (did
  // not move it in) or a consumer that holds the array gets a new one.
  if (!array || array->GetReferenceCount() != 1 || array->GetNumberOfComponents() != components ||
    array->GetNumberOfTuples() != tuples)
  {
    return newParallelFillArray(name, components, tuples);
  }
  array->SetName(name.c_str());
  // Clears the ranges and other facts cached about the old values.
  array->Modified();
  return array;
}

} // namespace shadelab
