#ifndef slParallelFillArray_h
#define slParallelFillArray_h
/**
 * @file slParallelFillArray.h
 * @brief A new vtkFloatArray that the caller is about to fill completely,
 * in parallel, with one write per value (the radiance filter's outputs, the
 * normals filter's Normals). C++ only, not wrapped.
 *
 * A freshly allocated array of many megabytes is not memory yet: the kernel
 * maps it page by page at the first write, and for the radiance filter's
 * outputs (60 MB for 1M points) those ~15000 4 KiB page faults cost as much
 * CPU time as the lighting itself. This allocates on 2 MiB boundaries and
 * asks Linux for transparent huge pages (madvise(MADV_HUGEPAGE), honoured
 * when /sys/kernel/mm/transparent_hugepage/enabled is "madvise" or
 * "always"), and maps the pages before returning (MADV_POPULATE_WRITE), so
 * the fill itself takes no page faults. The values are left
 * uninitialised, as SetNumberOfTuples() leaves them; nothing else changes:
 * VTK owns the memory and frees it with free().
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
