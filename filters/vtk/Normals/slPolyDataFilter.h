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
 * Pieces (MPI ranks in ParaView's pvbatch or pvserver): every one of these
 * filters computes a point's value from the polygons around it, so when the
 * output is asked for one piece of several, the filter asks its input for
 * one more level of ghost cells than it was asked for, computes with the
 * ghost cells as neighbours, and, when its own output was asked for no ghost
 * levels, removes the ghost cells from the output (vtkPolyData::
 * RemoveGhostCells(); points used only by ghost cells stay, marked as ghost
 * points). Values at the points of a piece's boundary are then those of the
 * whole mesh, on any number of pieces, provided the input generates ghost
 * cells on request (e.g. ParaView's D3 / RedistributeDataSet or
 * vtkExtractPolyDataPiece).
 *
 * @warning When the output is asked for ghost levels itself, all ghost cells
 * are kept (VTK marks no level on a ghost cell); values at points of the
 * outermost ghost level then see only part of their neighbourhood.
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

  /// Runs the request; after a successful REQUEST_DATA for one piece of
  /// several with no ghost levels asked, removes the output's ghost cells.
  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

protected:
  slPolyDataFilter();
  ~slPolyDataFilter() override;

  /// Asks the input for one more ghost level when the output is one piece of several.
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

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
