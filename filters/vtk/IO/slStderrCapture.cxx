#include "slStderrCapture.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <unistd.h>

namespace
{
std::mutex& captureMutex()
{
  static std::mutex m;
  return m;
}

std::atomic<bool> captureEnabled{ true };
} // namespace

void slStderrCapture::SetEnabled(bool enabled)
{
  captureEnabled = enabled;
}

bool slStderrCapture::GetEnabled()
{
  return captureEnabled;
}

slStderrCapture::slStderrCapture()
  : Lock(captureMutex())
{
  if (!captureEnabled)
  {
    return;
  }
  std::fflush(stderr);
  char name[] = "/tmp/shadelab-stderr-XXXXXX";
  this->File = mkstemp(name);
  if (this->File < 0)
  {
    return; // nothing captured: the library's lines stay visible
  }
  unlink(name);
  this->Saved = dup(2);
  if (this->Saved < 0 || dup2(this->File, 2) < 0)
  {
    close(this->File);
    this->File = -1;
  }
}

slStderrCapture::~slStderrCapture()
{
  if (this->File >= 0)
  {
    std::fflush(stderr);
    dup2(this->Saved, 2);
    close(this->Saved);
    close(this->File);
  }
}

std::string slStderrCapture::Text() const
{
  std::string text;
  if (this->File < 0)
  {
    return text;
  }
  std::fflush(stderr);
  char buffer[4096];
  for (off_t at = 0;;)
  {
    const ssize_t n = pread(this->File, buffer, sizeof(buffer), at);
    if (n <= 0 || text.size() > 65536)
    {
      break;
    }
    text.append(buffer, static_cast<size_t>(n));
    at += n;
  }
  std::string line;
  for (char c : text)
  {
    if (c == '\n')
    {
      line += "; ";
    }
    else
    {
      line += c;
    }
  }
  while (!line.empty() && (line.back() == ' ' || line.back() == ';'))
  {
    line.pop_back();
  }
  return line;
}
