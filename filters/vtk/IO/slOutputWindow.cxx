#include "slOutputWindow.h"

#include "slErrorCapture.h"
#include "slStderrCapture.h"

#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>

vtkStandardNewMacro(slOutputWindow);

void slOutputWindow::Install(bool echo)
{
  vtkNew<slOutputWindow> window;
  window->SetEcho(echo);
  vtkOutputWindow::SetInstance(window);
  vtkObject::GlobalWarningDisplayOn();
  slStderrCapture::SetEnabled(!echo);
  if (!echo)
  {
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
}

void slOutputWindow::DisplayText(const char* text)
{
  if (this->Echo)
  {
    this->Superclass::DisplayText(text);
  }
}

void slOutputWindow::DisplayErrorText(const char* text)
{
  slErrorCapture::Deliver(text, true);
  this->Superclass::DisplayErrorText(text);
}

void slOutputWindow::DisplayWarningText(const char* text)
{
  slErrorCapture::Deliver(text, false);
  this->Superclass::DisplayWarningText(text);
}

void slOutputWindow::DisplayGenericWarningText(const char* text)
{
  slErrorCapture::Deliver(text, false);
  this->Superclass::DisplayGenericWarningText(text);
}

void slOutputWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Echo: " << this->Echo << "\n";
}
