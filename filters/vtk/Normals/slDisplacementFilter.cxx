#include "slDisplacementFilter.h"

#include "slCoreBoundary.h"
#include "slDetailInputs.h"
#include "slPolyDataNormals.h"
#include "slUpdateOrThrow.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>

vtkStandardNewMacro(slDisplacementFilter);

slDisplacementFilter::slDisplacementFilter() = default;

slDisplacementFilter::~slDisplacementFilter() = default;

int slDisplacementFilter::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  slSurfaceFrames frames;
  slnormals::Texture height;
  if (!this->PrepareDetail(input, output, "Scale", this->Scale, false, 1, frames, height))
  {
    return 0;
  }
  vtkPoints* in = frames.mesh->GetPoints();
  vtkNew<vtkPoints> moved;
  moved->SetDataType(in->GetDataType());
  moved->SetNumberOfPoints(in->GetNumberOfPoints());
  if (moved->GetNumberOfPoints() != in->GetNumberOfPoints())
  {
    throw std::bad_alloc(); // VTK could not allocate them (see slSetNumberOfTuplesOrThrow)
  }
  vtkSMPTools::For(0, in->GetNumberOfPoints(), 4096, [&](vtkIdType b, vtkIdType e) {
    for (vtkIdType i = b; i < e; ++i)
    {
      const size_t s = static_cast<size_t>(i);
      const double h = height.sample(frames.uv[s].x, frames.uv[s].y, 0);
      const double d = this->Scale * (this->InvertHeight ? 1.0 - h : h);
      double p[3];
      in->GetPoint(i, p);
      moved->SetPoint(i, p[0] + d * frames.normal[s].x, p[1] + d * frames.normal[s].y, p[2] + d * frames.normal[s].z);
    }
  });
  vtkNew<vtkPolyData> displaced;
  displaced->ShallowCopy(frames.mesh);
  displaced->SetPoints(moved);
  vtkNew<slPolyDataNormals> normals;
  normals->SetInputData(displaced);
  normals->SplittingOff();
  normals->ConsistencyOff();
  // It fails for example for points moved beyond the float range by a large Scale.
  if (!slRunCore(this, output, [&] { slUpdateOrThrow(normals, "displaced mesh: "); }))
  {
    return 0;
  }
  output->ShallowCopy(normals->GetOutput());
  return 1;
}

void slDisplacementFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scale: " << this->Scale << "\n";
  os << indent << "InvertHeight: " << this->InvertHeight << "\n";
}
