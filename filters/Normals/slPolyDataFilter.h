#ifndef slPolyDataFilter_h
#define slPolyDataFilter_h
/**
 * @class   slPolyDataFilter
 * @brief   A vtkPolyDataAlgorithm that keeps the reason of its last failure.
 *
 * The ShadeLab::Normals filters derive from it: on bad input they call
 * Fail(), which reports the problem through vtkErrorMacro, empties the
 * output and keeps the one-line reason for GetErrorMessage(), so that callers
 * get it even when VTK's global warning display is off.
 *
 * @sa slPolyDataNormals slPolyDataTangents slNormalMapFilter
 */

#include "ShadeLabNormalsModule.h"

#include <vtkPolyDataAlgorithm.h>

#include <string>

class SHADELABNORMALS_EXPORT slPolyDataFilter : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(slPolyDataFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The reason the last update failed, or "" after success.
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

protected:
  slPolyDataFilter();
  ~slPolyDataFilter() override;

  /// Clears the error message; call at the start of RequestData.
  void ClearError() { this->ErrorMessage.clear(); }

  /// Reports @p problem, empties @p output; returns 0 for RequestData.
  int Fail(const std::string& problem, vtkPolyData* output);

private:
  slPolyDataFilter(const slPolyDataFilter&) = delete;
  void operator=(const slPolyDataFilter&) = delete;

  std::string ErrorMessage;
};

#endif
