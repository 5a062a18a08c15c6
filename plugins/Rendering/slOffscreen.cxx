#include "slOffscreen.h"

#include "shadelab/Error.h"

#include "slGLXContextCheck.h"

#include <vtkCallbackCommand.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkWindowToImageFilter.h>

#include <cstdlib>
#include <stdexcept>

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
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}
