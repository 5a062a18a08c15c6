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
 */

#include <string>

/// "" if a GLX context (OpenGL 3.2 core, as VTK asks) could be created on
/// $DISPLAY within @p attempts tries; otherwise the one-line reason, e.g.
/// "cannot create an OpenGL context on X display :0 (5 attempts): ...".
std::string slGLXContextProblem(int attempts = 6);

#endif
