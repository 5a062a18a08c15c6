#ifndef slParallelFillArray_h
#define slParallelFillArray_h
/**
 * @file slParallelFillArray.h
 * @brief A new vtkFloatArray that the caller is about to fill completely,
 * in parallel, with one write per value (the radiance filter's outputs, the
 * normals filter's Normals). C++ only, not wrapped.
 *
 * Arrays of 2 MiB or more are allocated by shadelab::allocateHugePages()
 * (HugePages.h): on transparent huge pages and mapped before they are
 * returned, so the fill takes no page faults (for the radiance filter's
 * outputs, 60 MB for 1M points, the ~15000 4 KiB faults otherwise cost as
 * much CPU time as the lighting itself). The values are left uninitialised,
 * as SetNumberOfTuples() leaves them; nothing else changes: VTK owns the
 * memory and frees it with free().
 *
 * A filter that runs again can hand its previous output array back with
 * recycleParallelFillArray(): when nothing else holds that array, it is
 * returned for refilling instead of a new one. A new array costs more than
 * its allocation: the kernel clears every page before the first write
 * (4 ms for the 48 MB of an 8M-triangle mesh's normals), and after another
 * filter has freed much memory in small pages, allocating them took
 * 26-65 ms, most of it in the kernel (a harness that ran vtkPolyDataNormals
 * between updates, as the normals bench does).
 */

#include "ShadeLabCommonModule.h"

#include <vtkFloatArray.h>
#include <vtkSmartPointer.h>

#include <string>

namespace shadelab
{

/// A float array named @p name with @p components × @p tuples values, uninitialised.
SHADELABCOMMON_EXPORT vtkSmartPointer<vtkFloatArray> newParallelFillArray(const std::string& name, int components, vtkIdType tuples);

/// @p previous itself, renamed @p name, marked modified and with its values
/// stale, when it is a float array of @p components × @p tuples values and
/// the caller's reference is its only one, so that no consumer can see it
/// change; else newParallelFillArray(@p name, @p components, @p tuples).
/// @p previous may be null; move it in (a copy kept by the caller is a
/// second reference).
SHADELABCOMMON_EXPORT vtkSmartPointer<vtkFloatArray> recycleParallelFillArray(
  vtkSmartPointer<vtkDataArray> previous, const std::string& name, int components, vtkIdType tuples);

} // namespace shadelab

#endif
