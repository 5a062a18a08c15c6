#include "slSurfaceDetailFilter.h"

#include "slCoreBoundary.h"
#include "slDetailInputs.h"
#include "slFiniteParameters.h"

#include <vtkPolyData.h>

slSurfaceDetailFilter::slSurfaceDetailFilter() = default;

slSurfaceDetailFilter::~slSurfaceDetailFilter()
{
  this->SetFileName(nullptr);
}

bool slSurfaceDetailFilter::PrepareDetail(vtkPolyData* input, vtkPolyData* output, const char* parameterName,
  double parameter, bool needTangents, int channelsRead, slSurfaceFrames& frames, slnormals::Texture& texture)
{
  output->Initialize();
  const std::string badParameter = slNonFiniteParameter({ { parameterName, parameter } });
  if (!badParameter.empty())
  {
    this->Fail(badParameter, output);
    return false;
  }
  return slRunCore(this, output,
           [&] { slPrepareDetail(input, this->FileName, needTangents, channelsRead, frames, texture); }) != 0;
}

void slSurfaceDetailFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
