#include "slErrorCapture.h"

#include <vtkObject.h>
#include <vtkObjectFactory.h>

slErrorCapture* slErrorCapture::New()
{
  VTK_STANDARD_NEW_BODY(slErrorCapture);
}

void slErrorCapture::Watch(vtkObject* object)
{
  object->AddObserver(vtkCommand::ErrorEvent, this);
  object->AddObserver(vtkCommand::WarningEvent, this);
}

void slErrorCapture::Execute(vtkObject*, unsigned long eventId, void* callData)
{
  if (eventId == vtkCommand::ErrorEvent && callData)
  {
    this->LastError = StripPreamble(static_cast<const char*>(callData));
  }
}

std::string slErrorCapture::StripPreamble(const std::string& message)
{
  std::string text = message;
  const size_t preamble = text.find("): ");
  if (preamble != std::string::npos)
  {
    text = text.substr(preamble + 3);
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
  {
    text.pop_back();
  }
  for (char& c : text)
  {
    c = c == '\n' ? ' ' : c;
  }
  return text;
}
