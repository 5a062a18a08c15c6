#include "slOffscreen.h"

#include "shadelab/Error.h"

#include "slGLXContextCheck.h"

#include <vtkCallbackCommand.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderWindow.h>
#include <vtkWindowToImageFilter.h>
#include <vtk_glew.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace
{
std::string sizeText(int width, int height)
{
  return std::to_string(width) + "x" + std::to_string(height);
}

/// "" if @p window (rendered, its context current) was drawn; else why not.
std::string drawProblem(vtkRenderWindow* window)
{
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!gl)
  {
    return "";
  }
  const int* size = window->GetSize();
  GLint viewport[2] = { 0, 0 };
  GLint renderbuffer = 0;
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
  const int largestWidth = std::min<int>(viewport[0], renderbuffer);
  const int largestHeight = std::min<int>(viewport[1], renderbuffer);
  if (largestWidth > 0 && largestHeight > 0 && (size[0] > largestWidth || size[1] > largestHeight))
  {
    return sizeText(size[0], size[1]) + " pixels is beyond the largest image this OpenGL can render, " +
      sizeText(largestWidth, largestHeight) + ": nothing was drawn";
  }
  vtkOpenGLFramebufferObject* fbo = gl->GetRenderFramebuffer();
  if (fbo && fbo->GetFBOIndex() != 0)
  {
    fbo->SaveCurrentBindingsAndBuffers(GL_READ_FRAMEBUFFER);
    fbo->Bind(GL_READ_FRAMEBUFFER);
    const char* reason = nullptr;
    const bool complete = vtkOpenGLFramebufferObject::GetFrameBufferStatus(GL_READ_FRAMEBUFFER, reason);
    fbo->RestorePreviousBindingsAndBuffers(GL_READ_FRAMEBUFFER);
    if (!complete)
    {
      return std::string("the ") + sizeText(size[0], size[1]) + " offscreen framebuffer is incomplete (" +
        (reason ? reason : "unknown reason") + "): nothing was drawn";
    }
  }
  return "";
}
} // namespace

std::string slWindowSizeProblem(int width, int height)
{
  if (width <= slMaximumWindowSize && height <= slMaximumWindowSize)
  {
    return "";
  }
  return sizeText(width, height) + " pixels is beyond the largest image that can be rendered, " +
    sizeText(slMaximumWindowSize, slMaximumWindowSize);
}

std::string slDisplayProblem()
{
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    return "no X display (DISPLAY is unset): Debian's VTK renders through X11; run under xvfb-run";
  }
  // VTK aborts the process when it cannot create its context: try first.
  return slGLXContextProblem();
}

vtkSmartPointer<vtkRenderWindow> slOffscreenWindow(int width, int height)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  // The connection slDisplayProblem() checked (and keeps open): a new one
  // could meet an X server that resets, and VTK aborts when it cannot open
  // one. Without a check, VTK opens its own as usual.
  if (void* display = slCheckedDisplay())
  {
    window->SetDisplayId(display);
  }
  // When it cannot create its GLX context (after slDisplayProblem() could),
  // VTK 9.1 calls abort() unless ExitEvent is observed; it then returns
  // without a context. Stop there with the reason instead of either.
  vtkNew<vtkCallbackCommand> noContext;
  noContext->SetCallback([](vtkObject*, unsigned long, void*, void*) {
    throw shadelab::Error("VTK cannot create an OpenGL context on the X display");
  });
  window->AddObserver(vtkCommand::ExitEvent, noContext);
  return window;
}

vtkSmartPointer<vtkImageData> slCaptureWindow(vtkRenderWindow* window)
{
  window->Render();
  window->MakeCurrent();
  const std::string problem = drawProblem(window);
  if (!problem.empty())
  {
    throw shadelab::Error(problem);
  }
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}
