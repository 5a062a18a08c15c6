#ifndef slGLXContextCheck_h
#define slGLXContextCheck_h
/**
 * @file slGLXContextCheck.h
 * @brief Whether an OpenGL context can be created on the X display, tried
 * before VTK tries.
 *
 * VTK 9.1's vtkXOpenGLRenderWindow calls abort() when it cannot open the
 * display or create a GLX context. Under load (several renders starting at
 * once on one Xvfb) context creation occasionally fails for a moment; a
 * process that aborted then left an empty stderr. slGLXContextProblem()
 * creates and destroys a context the way VTK will, retrying with a growing
 * pause, so a transient failure passes and a lasting one becomes a message.
 *
 * The connection of the first successful try stays open for the rest of the
 * process, and ShadeLab's offscreen windows render on it (slCheckedDisplay())
 * rather than open their own: an Xvfb started without -noreset (plain
 * xvfb-run) resets when its last client leaves, and refuses connections
 * while it does, so a connection opened after the check closed its own
 * could fail, and VTK 9.1 aborts on a failed connection.
 */

#include <string>

/// "" if a GLX context (OpenGL 3.2 core, as VTK asks) could be created on
/// $DISPLAY within @p attempts tries; otherwise the one-line reason, e.g.
/// "cannot create an OpenGL context on X display :0 (5 attempts): ...".
std::string slGLXContextProblem(int attempts = 6);

/// The X connection (a Display*) on which slGLXContextProblem() last created
/// a context, open until the process ends; null before any check succeeded.
void* slCheckedDisplay();

#endif
