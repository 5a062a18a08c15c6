#ifndef slOutputWindow_h
#define slOutputWindow_h
/**
 * @class   slOutputWindow
 * @brief   VTK's output window for programs that report problems themselves.
 *
 * Every error and warning VTK formats goes to the newest live slErrorCapture,
 * so the operation that failed can say why in its own one-line message.
 * With Echo off nothing is printed, and VTK's logger (which would print its
 * own copy of every message on stderr) is silenced, and so are the image
 * libraries' own lines (slStderrCapture); with Echo on, messages are also
 * shown as VTK normally shows them, and the libraries' lines as they print
 * them.
 *
 * Install() makes an slOutputWindow the output window of the process and
 * turns vtkObject::GlobalWarningDisplay on: VTK formats no message at all
 * while it is off, so turning it off would hide every reason.
 *
 * Caveats: it replaces the process-wide output window; meant for programs
 * (the shadelab tool), not for libraries loaded into ParaView or Python.
 *
 * @sa slErrorCapture vtkOutputWindow vtkLogger
 */

#include "ShadeLabIOModule.h"

#include <vtkOutputWindow.h>

class SHADELABIO_EXPORT slOutputWindow : public vtkOutputWindow
{
public:
  static slOutputWindow* New();
  vtkTypeMacro(slOutputWindow, vtkOutputWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Makes a new slOutputWindow with @p echo the process's output window.
  static void Install(bool echo);

  ///@{
  /// Also show messages as vtkOutputWindow does. Default off.
  vtkSetMacro(Echo, bool);
  vtkGetMacro(Echo, bool);
  vtkBooleanMacro(Echo, bool);
  ///@}

  void DisplayText(const char* text) override;
  void DisplayErrorText(const char* text) override;
  void DisplayWarningText(const char* text) override;
  void DisplayGenericWarningText(const char* text) override;

protected:
  slOutputWindow() = default;
  ~slOutputWindow() override = default;

private:
  slOutputWindow(const slOutputWindow&) = delete;
  void operator=(const slOutputWindow&) = delete;

  bool Echo = false;
};

#endif
