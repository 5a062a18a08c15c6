#ifndef slOffscreen_h
#define slOffscreen_h
/**
 * @file slOffscreen.h
 * @brief What every ShadeLab renderer does the same way: check for an X
 * display, open a deterministic offscreen window, capture it as an image.
 * C++ only (not wrapped); shadelab-viewer captures its Qt window the same way.
 */

#include "ShadeLabRenderPassesModule.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkImageData;
class vtkRenderWindow;

/// The one-line reason rendering is impossible here, or "" if an X display
/// is available (Debian's VTK renders through X11 only) and an OpenGL
/// context can be created on it (slGLXContextProblem(), which retries).
SHADELABRENDERPASSES_EXPORT std::string slDisplayProblem();

/// An offscreen window of @p width x @p height, multisampling off, so that
/// the same scene gives the same pixels. After slDisplayProblem() returned
/// "", the window renders on the X connection that check opened and kept, so
/// VTK opens none of its own (it would abort() if that failed). Where VTK
/// would abort() because it cannot create its OpenGL context, rendering it
/// throws shadelab::Error.
SHADELABRENDERPASSES_EXPORT vtkSmartPointer<vtkRenderWindow> slOffscreenWindow(int width, int height);

/// Renders @p window and returns its back buffer as RGB unsigned char, row 0
/// at the bottom.
SHADELABRENDERPASSES_EXPORT vtkSmartPointer<vtkImageData> slCaptureWindow(vtkRenderWindow* window);

#endif
