#include "slOffscreen.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkWindowToImageFilter.h>

#include <cstdlib>

std::string slDisplayProblem()
{
  const char* display = std::getenv("DISPLAY");
  return display && *display
    ? std::string()
    : std::string("no X display (DISPLAY is unset): Debian's VTK renders through X11; run under xvfb-run");
}

vtkSmartPointer<vtkRenderWindow> slOffscreenWindow(int width, int height)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
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
