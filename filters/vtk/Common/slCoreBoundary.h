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

#include <vtkDataObject.h>
#include <vtkObject.h>
#include <vtkSetGet.h>

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

#endif
