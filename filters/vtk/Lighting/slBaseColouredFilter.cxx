#include "slBaseColouredFilter.h"
#include "slCoreBoundary.h"

#include "slDiffuseColors.h"
#include "slShadingInputs.h"

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

std::unique_ptr<const shadelab::ShadingInputs> slBaseColouredFilter::PrepareShading(
  vtkPolyData* input, vtkPolyData* output, const shadelab::LightingSetup& setup)
{
  std::vector<glm::vec3> base;
  if (!this->GetBaseColours(input, output, base))
  {
    return nullptr;
  }
  vtkDataArray* tangents = nullptr;
  if (!this->GetTangents(input, output, setup, tangents))
  {
    return nullptr;
  }
  output->ShallowCopy(input);
  return std::make_unique<const shadelab::ShadingInputs>(input, tangents, std::move(base), setup);
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
