#ifndef shadelab_Error_h
#define shadelab_Error_h
/**
 * @file Error.h
 * @brief The one way VTK-free code reports a failure: it throws shadelab::Error.
 *
 * what() is the whole message on one line, in the form the programs print:
 * `FILE: PLACE: reason` (the place is a key path, "line N", a light index;
 * left out when the file alone says where; code that is given data, not a
 * file, names what it was given, e.g. "input mesh"). The VTK filters run
 * such code, and their internal helpers that throw it too, through
 * slRunCore() (slCoreBoundary.h): the one place that turns it into
 * vtkErrorMacro and a failed request. slUpdateOrThrow() turns a failed VTK
 * request back into a shadelab::Error for the programs.
 *
 * Functions whose purpose is to find a problem (sceneValueProblem(),
 * slMeshFileProblem(), ...) return its description, "" for none: the answer
 * to the question they are asked, not a failure.
 */

#include <stdexcept>
#include <string>

namespace shadelab
{

/// A failed operation of the VTK-free code; what() is the one-line message.
/// Visible from every library whatever its visibility settings (the static
/// cores are compiled hidden): it is thrown in one shared library and caught
/// in another.
class __attribute__((visibility("default"))) Error : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

} // namespace shadelab

#endif
