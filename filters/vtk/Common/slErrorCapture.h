#ifndef slErrorCapture_h
#define slErrorCapture_h
/**
 * @class   slErrorCapture
 * @brief   Records the text of the VTK errors and warnings of one operation.
 *
 * VTK objects report problems through vtkErrorMacro, which formats a
 * multi-line message and carries on. slErrorCapture keeps the first error's
 * own text (without the "ERROR: In file, line" and "Class (0x...): "
 * preambles) so ShadeLab can turn it into one line naming the file: the
 * first, because later ones are its consequences (the executive's "returned
 * failure for request").
 *
 * It hears two ways: the objects given to Watch() (their ErrorEvent and
 * WarningEvent), and, while it exists, every message that reaches VTK's
 * output window when that window is an slOutputWindow (the newest live
 * capture gets it). The latter catches the objects a reader or writer makes
 * internally. Both need vtkObject::GlobalWarningDisplay on: VTK formats no
 * message at all while it is off.
 *
 * Internal helper: not wrapped.
 *
 * @sa slOutputWindow slUpdateOrThrow
 */

#include "ShadeLabCommonModule.h"

#include <vtkCommand.h>

#include <string>

class vtkObject;

class SHADELABCOMMON_EXPORT slErrorCapture : public vtkCommand
{
public:
  static slErrorCapture* New();
  vtkTypeMacro(slErrorCapture, vtkCommand);

  /// Observe ErrorEvent and WarningEvent of @p object (which then prints nothing).
  void Watch(vtkObject* object);
  /// Stop observing @p object; needed when it outlives the operation, since
  /// it holds a reference that keeps this capture live.
  void Unwatch(vtkObject* object);

  void Execute(vtkObject* caller, unsigned long eventId, void* callData) override;

  bool HasError() const { return !this->Error.empty(); }
  /// The first error's own text, on one line; "" if none. A VTK array's
  /// "Unable to allocate N elements of size M bytes." reads "out of memory
  /// (unable to allocate N elements of size M bytes)", as ShadeLab says it.
  const std::string& GetError() const { return this->Error; }
  /// The first warning's own text, on one line; "" if none.
  const std::string& GetWarning() const { return this->Warning; }
  void Clear();

  /// Records @p message (a VTK error if @p isError, else a warning) in the
  /// newest live slErrorCapture. False if there is none.
  static bool Deliver(const char* message, bool isError);

  /// The text of a VTK message after its "ERROR: In FILE, line N" line and
  /// its "Class (0x...): " preamble, on one line.
  static std::string StripPreamble(const std::string& message);

protected:
  slErrorCapture();
  ~slErrorCapture() override;

private:
  void Record(const char* message, bool isError);

  std::string Error;
  std::string Warning;
};

#endif
