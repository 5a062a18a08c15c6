#include "slPolyDataFilter.h"
#include "slCoreBoundary.h"

#include <vtkCellData.h>
#include <vtkDataSetAttributes.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

namespace
{
/// Whether @p outInfo asks for one piece of several.
bool askedForAPiece(vtkInformation* outInfo)
{
  return outInfo && outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) > 1;
}

int askedGhostLevels(vtkInformation* outInfo)
{
  return outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS())
    : 0;
}
} // namespace

slPolyDataFilter::slPolyDataFilter() = default;
slPolyDataFilter::~slPolyDataFilter() = default;

int slPolyDataFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The executive has already copied the output's piece request upstream.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  if (inInfo && askedForAPiece(outInfo))
  {
    // A point on the piece's boundary needs every polygon around it: one
    // more layer of cells than the output's own ghost request.
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), askedGhostLevels(outInfo) + 1);
  }
  return 1;
}

vtkTypeBool slPolyDataFilter::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const vtkTypeBool result = slProcessRequestSafely(this, outputVector, "",
    [&] { return this->Superclass::ProcessRequest(request, inputVector, outputVector); });
  if (result && request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
  {
    vtkInformation* outInfo = outputVector->GetInformationObject(0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector);
    if (output && askedForAPiece(outInfo) && askedGhostLevels(outInfo) == 0 &&
      output->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()))
    {
      output->RemoveGhostCells();
    }
  }
  return result;
}

int slPolyDataFilter::Fail(const std::string& problem, vtkPolyData* output)
{
  output->Initialize();
  vtkErrorMacro(<< problem);
  return 0;
}

void slPolyDataFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
