#ifndef slErrorCapture_h
#define slErrorCapture_h
/**
 * @class   slErrorCapture
 * @brief   Observer that records the text of VTK error and warning events.
 *
 * VTK readers report problems through vtkErrorMacro, which formats a
 * multi-line message and then carries on. slErrorCapture, attached to such a
 * reader, keeps the last error's own text (without the "ERROR: In file,
 * line" preamble) so ShadeLab can turn it into one line naming the file.
 * Internal helper: not wrapped.
 */

#include "ShadeLabIOModule.h"

#include <vtkCommand.h>

#include <string>

class vtkObject;

class SHADELABIO_EXPORT slErrorCapture : public vtkCommand
{
public:
  static slErrorCapture* New();
  vtkTypeMacro(slErrorCapture, vtkCommand);

  /// Observe ErrorEvent and WarningEvent of @p object (which then prints nothing).
  void Watch(vtkObject* object);

  void Execute(vtkObject* caller, unsigned long eventId, void* callData) override;

  bool HasError() const { return !this->LastError.empty(); }
  /// The message of the last error, stripped to its own text.
  const std::string& GetLastError() const { return this->LastError; }
  void Clear() { this->LastError.clear(); }

  /// The text of a VTK error message after its "Class (0x...): " preamble.
  static std::string StripPreamble(const std::string& message);

protected:
  slErrorCapture() = default;
  ~slErrorCapture() override = default;

private:
  std::string LastError;
};

#endif
