#include "slErrorCapture.h"

#include <vtkObject.h>
#include <vtkObjectFactory.h>

#include <algorithm>
#include <cctype>
#include <mutex>
#include <vector>

namespace
{
// The live captures, oldest first. VTK reports from worker threads too, so
// the list is shared and locked rather than thread-local.
std::mutex& liveLock()
{
  static std::mutex lock;
  return lock;
}

std::vector<slErrorCapture*>& live()
{
  static std::vector<slErrorCapture*> captures;
  return captures;
}
} // namespace

slErrorCapture* slErrorCapture::New()
{
  VTK_STANDARD_NEW_BODY(slErrorCapture);
}

slErrorCapture::slErrorCapture()
{
  std::lock_guard<std::mutex> guard(liveLock());
  live().push_back(this);
}

slErrorCapture::~slErrorCapture()
{
  std::lock_guard<std::mutex> guard(liveLock());
  live().erase(std::remove(live().begin(), live().end(), this), live().end());
}

void slErrorCapture::Watch(vtkObject* object)
{
  object->AddObserver(vtkCommand::ErrorEvent, this);
  object->AddObserver(vtkCommand::WarningEvent, this);
}

void slErrorCapture::Unwatch(vtkObject* object)
{
  object->RemoveObserver(this);
}

void slErrorCapture::Execute(vtkObject*, unsigned long eventId, void* callData)
{
  if (callData && (eventId == vtkCommand::ErrorEvent || eventId == vtkCommand::WarningEvent))
  {
    std::lock_guard<std::mutex> guard(liveLock());
    this->Record(static_cast<const char*>(callData), eventId == vtkCommand::ErrorEvent);
  }
}

void slErrorCapture::Clear()
{
  std::lock_guard<std::mutex> guard(liveLock());
  this->Error.clear();
  this->Warning.clear();
}

bool slErrorCapture::Deliver(const char* message, bool isError)
{
  std::lock_guard<std::mutex> guard(liveLock());
  if (live().empty() || !message)
  {
    return false;
  }
  live().back()->Record(message, isError);
  return true;
}

void slErrorCapture::Record(const char* message, bool isError)
{
  std::string& first = isError ? this->Error : this->Warning;
  if (first.empty())
  {
    first = StripPreamble(message);
    // A VTK array that could not allocate its storage (vtkGenericDataArray):
    // said as ShadeLab says it, for every caller to recognise.
    const std::string allocation = "Unable to allocate ";
    if (first.compare(0, allocation.size(), allocation) == 0)
    {
      if (first.back() == '.')
      {
        first.pop_back();
      }
      first = "out of memory (u" + first.substr(1) + ")";
    }
  }
}

std::string slErrorCapture::StripPreamble(const std::string& message)
{
  std::string text = message;
  // "ERROR: In /path/file.cxx, line 12\n", "Warning: In ...", "Generic Warning: In ..."
  const size_t newline = text.find('\n');
  if (newline != std::string::npos && text.find(": In ") < newline && text.find(", line ") < newline)
  {
    text = text.substr(newline + 1);
  }
  // "vtkSomeClass (0x55d0c0ffee00): "
  const size_t open = text.find(" (");
  const size_t close = text.find("): ");
  if (open != std::string::npos && close != std::string::npos && open < close &&
    std::all_of(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(open),
      [](unsigned char c) { return std::isalnum(c) || c == '_' || c == ':'; }))
  {
    text = text.substr(close + 3);
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
  {
    text.pop_back();
  }
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}
