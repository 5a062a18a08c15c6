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
 */

#include "ShadeLabCommonModule.h"

#include <vtkFloatArray.h>
#include <vtkSmartPointer.h>

#include <string>

namespace shadelab
{

/// A float array named @p name with @p components × @p tuples values, uninitialised.
SHADELABCOMMON_EXPORT vtkSmartPointer<vtkFloatArray> newParallelFillArray(const std::string& name, int components, vtkIdType tuples);

} // namespace shadelab

#endif
