/* Preloaded into `shadelab render` by test_glx_faults.py: makes GLX context
 * creation fail on chosen attempts, the way it fails for a moment when many
 * processes start rendering at once on one X server, and X connections fail
 * on chosen attempts, the way an Xvfb refuses them while it resets after its
 * last client left (xvfb-run without -noreset).
 *
 * Context attempts are every call that creates a context, numbered from 0 in
 * the process: glXCreateContext, glXCreateNewContext, and
 * glXCreateContextAttribsARB as glXGetProcAddress(ARB) hands it out;
 * connection attempts are the calls of XOpenDisplay. With
 * SHADELAB_GLX_FAIL="FIRST COUNT" (contexts) or SHADELAB_XOPEN_FAIL="FIRST
 * COUNT" (connections) attempts FIRST .. FIRST + COUNT - 1 fail (return
 * null); COUNT -1 means every attempt from FIRST on. */
#define _GNU_SOURCE
#include <GL/glx.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef GLXContext (*CreateContextAttribs)(Display*, GLXFBConfig, GLXContext, Bool, const int*);
typedef void (*(*GetProcAddress)(const GLubyte*))(void);

static long contextAttempts = 0;
static long connectionAttempts = 0;

/* Whether this attempt (*attempts, then counted) fails by the rule in the
 * environment variable @ruleVariable. */
static int failThisAttempt(long* attempts, const char* ruleVariable)
{
  long first = 0, count = 0;
  const char* rule = getenv(ruleVariable);
  const long attempt = (*attempts)++;
  if (!rule || sscanf(rule, "%ld %ld", &first, &count) != 2)
  {
    return 0;
  }
  return attempt >= first && (count < 0 || attempt < first + count);
}

static void* next(const char* name)
{
  return dlsym(RTLD_NEXT, name);
}

static int failContextAttempt(void)
{
  return failThisAttempt(&contextAttempts, "SHADELAB_GLX_FAIL");
}

static CreateContextAttribs realCreateContextAttribs = NULL;

static GLXContext failingCreateContextAttribs(
  Display* display, GLXFBConfig config, GLXContext share, Bool direct, const int* attributes)
{
  return failContextAttempt() ? NULL : realCreateContextAttribs(display, config, share, direct, attributes);
}

static void (*wrapProc(const GLubyte* name, void (*proc)(void)))(void)
{
  if (proc && strcmp((const char*)name, "glXCreateContextAttribsARB") == 0)
  {
    realCreateContextAttribs = (CreateContextAttribs)proc;
    return (void (*)(void))failingCreateContextAttribs;
  }
  return proc;
}

void (*glXGetProcAddressARB(const GLubyte* name))(void)
{
  return wrapProc(name, ((GetProcAddress)next("glXGetProcAddressARB"))(name));
}

void (*glXGetProcAddress(const GLubyte* name))(void)
{
  return wrapProc(name, ((GetProcAddress)next("glXGetProcAddress"))(name));
}

GLXContext glXCreateContext(Display* display, XVisualInfo* visual, GLXContext share, Bool direct)
{
  typedef GLXContext (*Real)(Display*, XVisualInfo*, GLXContext, Bool);
  return failContextAttempt() ? NULL : ((Real)next("glXCreateContext"))(display, visual, share, direct);
}

GLXContext glXCreateNewContext(Display* display, GLXFBConfig config, int type, GLXContext share, Bool direct)
{
  typedef GLXContext (*Real)(Display*, GLXFBConfig, int, GLXContext, Bool);
  return failContextAttempt() ? NULL : ((Real)next("glXCreateNewContext"))(display, config, type, share, direct);
}

Display* XOpenDisplay(const char* name)
{
  typedef Display* (*Real)(const char*);
  return failThisAttempt(&connectionAttempts, "SHADELAB_XOPEN_FAIL") ? NULL : ((Real)next("XOpenDisplay"))(name);
}
