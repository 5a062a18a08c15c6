#include "slGLXContextCheck.h"

#include <GL/glx.h>
#include <X11/Xlib.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <mutex>
#include <thread>
#include <unistd.h>

namespace
{
bool xErrorSeen = false;

int recordXError(Display*, XErrorEvent*)
{
  xErrorSeen = true;
  return 0;
}

using CreateContextAttribs = GLXContext (*)(Display*, GLXFBConfig, GLXContext, Bool, const int*);

/// XOpenDisplay, without the lines Xlib prints on stderr when the server
/// refuses the connection ("Authorization required, ..."): the caller says
/// what failed, on one line.
Display* openDisplayQuietly()
{
  std::fflush(stderr);
  const int saved = ::dup(STDERR_FILENO);
  const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (saved >= 0 && null >= 0)
  {
    ::dup2(null, STDERR_FILENO);
  }
  Display* display = XOpenDisplay(nullptr);
  if (saved >= 0 && null >= 0)
  {
    ::dup2(saved, STDERR_FILENO);
  }
  for (int fd : { saved, null })
  {
    if (fd >= 0)
    {
      ::close(fd);
    }
  }
  return display;
}

/// The connection of the last successful try, kept open for the rest of
/// the process (slCheckedDisplay()); guarded by displayMutex.
Display* keptDisplay = nullptr;
std::mutex displayMutex;

/// One try on @p display: "" or what failed.
std::string tryContext(Display* display)
{
  std::string problem;
  int errorBase = 0, eventBase = 0;
  if (!glXQueryExtension(display, &errorBase, &eventBase))
  {
    return "the X server has no GLX extension";
  }
  // The frame-buffer configuration vtkXOpenGLRenderWindow asks for.
  const int attributes[] = { GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT, GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_RED_SIZE, 1,
    GLX_GREEN_SIZE, 1, GLX_BLUE_SIZE, 1, GLX_DEPTH_SIZE, 1, GLX_DOUBLEBUFFER, True, None };
  int count = 0;
  GLXFBConfig* configs = glXChooseFBConfig(display, DefaultScreen(display), attributes, &count);
  if (!configs || count == 0)
  {
    problem = "no suitable GLX frame-buffer configuration";
  }
  else
  {
    XErrorHandler previous = XSetErrorHandler(recordXError);
    xErrorSeen = false;
    auto create = reinterpret_cast<CreateContextAttribs>(
      glXGetProcAddressARB(reinterpret_cast<const GLubyte*>("glXCreateContextAttribsARB")));
    const int version[] = { GLX_CONTEXT_MAJOR_VERSION_ARB, 3, GLX_CONTEXT_MINOR_VERSION_ARB, 2, None };
    GLXContext context = create ? create(display, configs[0], nullptr, True, version) : nullptr;
    XSync(display, False);
    if (xErrorSeen && context)
    {
      glXDestroyContext(display, context);
      context = nullptr;
    }
    if (!context)
    {
      problem = "GLX context creation failed";
    }
    else
    {
      glXDestroyContext(display, context);
    }
    XSync(display, False);
    XSetErrorHandler(previous);
  }
  if (configs)
  {
    XFree(configs);
  }
  return problem;
}

/// One try on the kept connection, or on a new one that is kept if the try
/// succeeds: "" or what failed. Call with displayMutex held.
std::string tryKeptContext()
{
  if (keptDisplay)
  {
    return tryContext(keptDisplay);
  }
  Display* display = openDisplayQuietly();
  if (!display)
  {
    return "cannot connect to the X server";
  }
  std::string problem = tryContext(display);
  if (problem.empty())
  {
    keptDisplay = display;
  }
  else
  {
    XCloseDisplay(display);
  }
  return problem;
}
} // namespace

std::string slGLXContextProblem(int attempts)
{
  const std::lock_guard<std::mutex> lock(displayMutex);
  std::string problem;
  for (int attempt = 0; attempt < attempts; ++attempt)
  {
    if (attempt > 0)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(25 << attempt));
    }
    problem = tryKeptContext();
    if (problem.empty())
    {
      return problem;
    }
  }
  const char* name = std::getenv("DISPLAY");
  return "cannot create an OpenGL context on X display " + std::string(name ? name : "") + " (" +
    std::to_string(attempts) + " attempts): " + problem;
}

void* slCheckedDisplay()
{
  const std::lock_guard<std::mutex> lock(displayMutex);
  return keptDisplay;
}
