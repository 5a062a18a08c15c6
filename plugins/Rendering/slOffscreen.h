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

/// The largest width and height of a window ShadeLab renders, in pixels:
/// GL_MAX_RENDERBUFFER_SIZE and GL_MAX_VIEWPORT_DIMS of Debian 12's Mesa
/// (llvmpipe, what CI renders with; 16384 as well on common GPU drivers).
/// Beyond it VTK's framebuffer cannot be made and the picture stays black.
/// Renderers refuse a larger composite before any work
/// (slWindowSizeProblem()); slCaptureWindow() checks the actual context's
/// limits as well.
constexpr int slMaximumWindowSize = 16384;

/// "" if a window of @p width x @p height fits slMaximumWindowSize; else the
/// one-line problem ("20000x64 pixels is beyond the largest image that can be
/// rendered, 16384x16384").
SHADELABRENDERPASSES_EXPORT std::string slWindowSizeProblem(int width, int height);

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
/// at the bottom. Throws shadelab::Error if the window could not be drawn
/// (it is larger than its OpenGL context's largest renderbuffer or viewport,
/// or its framebuffer is incomplete) rather than return a black image.
SHADELABRENDERPASSES_EXPORT vtkSmartPointer<vtkImageData> slCaptureWindow(vtkRenderWindow* window);

#endif
