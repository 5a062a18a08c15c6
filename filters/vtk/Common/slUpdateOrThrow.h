#ifndef slUpdateOrThrow_h
#define slUpdateOrThrow_h
/**
 * @file slUpdateOrThrow.h
 * @brief Running a VTK algorithm or call and getting its failure back as a
 * shadelab::Error: the one way the programs, and filters that run a
 * pipeline inside, take VTK's errors.
 *
 * A ShadeLab filter fails as VTK's do (vtkErrorMacro, empty output, failed
 * request; see slCoreBoundary.h). These helpers watch the object's
 * ErrorEvent with an slErrorCapture while it runs, and on failure throw a
 * shadelab::Error whose what() is the first error's text on one line (the
 * cause; later ones are its consequences). Errors of other objects (an
 * upstream reader, a writer's internal VTK writer) reach the same capture
 * when slOutputWindow is VTK's output window, as in the shadelab programs.
 *
 * @warning VTK formats no message while vtkObject::GlobalWarningDisplay is
 * off; the error then reads "CLASS failed" without the reason. It is on by
 * default and slOutputWindow::Install() turns it on.
 *
 * Internal helper: not wrapped.
 *
 * @sa slRunCore slErrorCapture slOutputWindow
 */

#include "ShadeLabCommonModule.h"
#include "slErrorCapture.h"

#include "shadelab/Error.h"

#include <vtkNew.h>

#include <string>
#include <utility>

class vtkAlgorithm;

/// Updates @p algorithm (all its output ports). Throws shadelab::Error with
/// @p context (e.g. "mesh.obj: ") followed by the first VTK error's text if
/// the update fails.
SHADELABCOMMON_EXPORT void slUpdateOrThrow(vtkAlgorithm* algorithm, const std::string& context = std::string());

/// Runs @p call (returning true on success, as a VTK method's int or bool
/// does) on @p object. Throws shadelab::Error with @p context followed by
/// the first VTK error's text if it returns false.
template <class Call>
void slCallOrThrow(vtkObject* object, Call&& call, const std::string& context = std::string())
{
  vtkNew<slErrorCapture> capture;
  bool succeeded = false;
  {
    // Unwatched on every way out (@p call may throw): a watched object keeps
    // the capture alive, and a live capture hears every VTK message.
    struct Watching
    {
      slErrorCapture* Capture;
      vtkObject* Object;
      ~Watching() { this->Capture->Unwatch(this->Object); }
    } watching{ capture, object };
    capture->Watch(object);
    succeeded = static_cast<bool>(std::forward<Call>(call)());
  }
  if (!succeeded)
  {
    throw shadelab::Error(
      context + (capture->HasError() ? capture->GetError() : std::string(object->GetClassName()) + " failed"));
  }
}

#endif
