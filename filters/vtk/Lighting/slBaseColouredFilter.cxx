#include "slBaseColouredFilter.h"
#include "slCoreBoundary.h"

#include "slDiffuseColors.h"

#include <vtkImageData.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkCxxSetObjectMacro(slBaseColouredFilter, DiffuseTexture, vtkImageData);

slBaseColouredFilter::slBaseColouredFilter() = default;

slBaseColouredFilter::~slBaseColouredFilter()
{
  this->SetDiffuseColorArrayName(nullptr);
  this->SetDiffuseTexture(nullptr);
  this->SetDiffuseTextureFileName(nullptr);
}

vtkMTimeType slBaseColouredFilter::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->DiffuseTexture && this->DiffuseTexture->GetMTime() > t)
  {
    t = this->DiffuseTexture->GetMTime();
  }
  return t;
}

bool slBaseColouredFilter::GetBaseColours(vtkPolyData* input, vtkPolyData* output, std::vector<glm::vec3>& base)
{
  return slRunCore(this, output, [&] {
    shadelab::baseColourPerPoint(
      input, this->DiffuseColorArrayName, this->DiffuseTextureFileName, this->DiffuseTexture, base);
  });
}

void slBaseColouredFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DiffuseColorArrayName: " << (this->DiffuseColorArrayName ? this->DiffuseColorArrayName : "(none)")
     << "\n";
  os << indent << "DiffuseTexture: " << this->DiffuseTexture << "\n";
  os << indent << "DiffuseTextureFileName: "
     << (this->DiffuseTextureFileName ? this->DiffuseTextureFileName : "(none)") << "\n";
}
