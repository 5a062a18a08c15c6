#ifndef slPolyDataFilter_h
#define slPolyDataFilter_h
/**
 * @class   slPolyDataFilter
 * @brief   A vtkPolyDataAlgorithm that fails as VTK's do and computes pieces with ghost cells.
 *
 * The ShadeLab::Normals filters derive from it: on bad input they call
 * Fail(), which reports the problem on one line through vtkErrorMacro,
 * empties the output and fails the request (slUpdateOrThrow() gives the
 * line back); the VTK-free code they run reports through slRunCore().
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

  /// Runs the request; after a successful REQUEST_DATA for one piece of
  /// several with no ghost levels asked, removes the output's ghost cells.
  /// A request that throws (std::bad_alloc: "out of memory (in CLASS)")
  /// fails as a VTK error (slProcessRequestSafely()).
  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

protected:
  slPolyDataFilter();
  ~slPolyDataFilter() override;

  /// Asks the input for one more ghost level when the output is one piece of several.
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// Reports @p problem (vtkErrorMacro), empties @p output; returns 0 for RequestData.
  int Fail(const std::string& problem, vtkPolyData* output);

private:
  slPolyDataFilter(const slPolyDataFilter&) = delete;
  void operator=(const slPolyDataFilter&) = delete;
};

#endif
