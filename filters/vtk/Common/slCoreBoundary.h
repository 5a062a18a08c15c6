#ifndef slCoreBoundary_h
#define slCoreBoundary_h
/**
 * @file slCoreBoundary.h
 * @brief The one place where the VTK-free code's errors become VTK's.
 *
 * VTK-free code (the lighting core, the `sl*Core.h` algorithms, a filter's
 * internal helpers) reports a failure by throwing shadelab::Error, whose
 * what() is one line, `FILE: PLACE: reason`. A VTK filter runs that code
 * through slRunCore(): the exception becomes vtkErrorMacro with that line,
 * an empty output and a failed request (RequestData returns 0, so Update()
 * fails), as VTK's own filters fail. The line then reaches whoever listens
 * to VTK errors: the filter's ErrorEvent observers, or VTK's output window
 * (slOutputWindow hands it to the newest live slErrorCapture). A caller that
 * wants the failure back as a shadelab::Error uses slUpdateOrThrow().
 *
 * Internal helper: not wrapped.
 *
 * @sa shadelab::Error slUpdateOrThrow slErrorCapture
 */

#include "shadelab/Error.h"
#include "shadelab/OutOfMemory.h"

#include <vtkAbstractArray.h>
#include <vtkDataObject.h>
#include <vtkInformationVector.h>
#include <vtkObject.h>
#include <vtkSetGet.h>

#include <exception>
#include <new>
#include <string>
#include <utility>

/// Runs @p work, a callable taking no argument, for @p self (whose name goes
/// in VTK's message). True if it returned; false, after vtkErrorMacro with
/// the exception's one-line message, if it threw shadelab::Error.
template <class Work>
bool slRunCore(vtkObject* self, Work&& work)
{
  try
  {
    std::forward<Work>(work)();
    return true;
  }
  catch (const shadelab::Error& error)
  {
    vtkErrorWithObjectMacro(self, << error.what());
    return false;
  }
}

/// slRunCore() for a RequestData: 1 on success; on a shadelab::Error,
/// vtkErrorMacro, @p output emptied (nothing half-computed is passed on) and 0.
template <class Work>
int slRunCore(vtkObject* self, vtkDataObject* output, Work&& work)
{
  if (slRunCore(self, std::forward<Work>(work)))
  {
    return 1;
  }
  if (output)
  {
    output->Initialize();
  }
  return 0;
}

/// @p array->SetNumberOfTuples(@p tuples), or std::bad_alloc where VTK
/// could not allocate them: VTK 9.1 then only reports "Unable to allocate"
/// and leaves the array as it was, often without storage, which code that
/// goes on to fill it would write through. For a filter's RequestData
/// (slProcessRequestSafely() turns the exception into its failure).
inline void slSetNumberOfTuplesOrThrow(vtkAbstractArray* array, vtkIdType tuples)
{
  array->SetNumberOfTuples(tuples);
  if (array->GetNumberOfTuples() != tuples)
  {
    throw std::bad_alloc();
  }
}

/// Runs @p request, a filter's call of Superclass::ProcessRequest(), for
/// @p self so that no exception leaves through VTK's executive: one that did
/// would leave the executive inside the request, and refuse the filter's
/// next update ("UpdateInformation invoked during another request"), as in
/// a batch that goes on after a mesh that did not fit in memory. An
/// exception that says memory ran out (shadelab::isOutOfMemory())
/// becomes vtkErrorMacro "@p prefix out of memory (in CLASS)",
/// another std::exception "@p prefix WHAT"; the output on port 0 is emptied
/// and 0 returned.
template <class Request>
vtkTypeBool slProcessRequestSafely(
  vtkObject* self, vtkInformationVector* outputVector, const char* prefix, Request&& request)
{
  std::string problem;
  try
  {
    return std::forward<Request>(request)();
  }
  catch (const std::exception& e)
  {
    problem = shadelab::isOutOfMemory(e) ? std::string("out of memory (in ") + self->GetClassName() + ")" : e.what();
  }
  if (vtkDataObject* output = outputVector ? vtkDataObject::GetData(outputVector) : nullptr)
  {
    output->Initialize();
  }
  vtkErrorWithObjectMacro(self, << prefix << problem);
  return 0;
}

#endif
