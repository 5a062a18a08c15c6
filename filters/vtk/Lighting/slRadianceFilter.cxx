#include "slRadianceFilter.h"
#include "shadelab/slAtomicMinimum.h"

#include "slLightingSetup.h"
#include "slRadianceKernel.h"
#include "slShadingInputs.h"

#include <vtkFloatArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>

#include <atomic>
#include <vector>

vtkStandardNewMacro(slRadianceFilter);

slRadianceFilter::slRadianceFilter() = default;

slRadianceFilter::~slRadianceFilter() = default;

int slRadianceFilter::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  using namespace shadelab;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  LightingSetup setup;
  // The kernel finds normals without a direction as it shades (one pass over
  // them, not two).
  if (!this->PrepareLighting(input, output, true, setup, false))
  {
    return 0;
  }
  const auto shading = this->PrepareShading(input, output, setup);
  if (!shading)
  {
    return 0;
  }
  const vtkIdType n = input->GetNumberOfPoints();
  auto ambient = rgbArray("Ambient", n), diffuseOut = rgbArray("Diffuse", n), specular = rgbArray("Specular", n),
       emission = rgbArray("Emission", n), radiance = rgbArray("Radiance", n);
  std::vector<vtkSmartPointer<vtkFloatArray>> perLight;
  RadianceKernelOutput out;
  if (this->PerLightArrays)
  {
    for (size_t l = 0; l < setup.lights.size(); ++l)
    {
      perLight.push_back(rgbArray("Radiance_" + std::to_string(l), n));
      out.perLight.push_back(perLight.back()->GetPointer(0));
    }
  }
  out.ambient = ambient->GetPointer(0);
  out.diffuse = diffuseOut->GetPointer(0);
  out.specular = specular->GetPointer(0);
  out.emission = emission->GetPointer(0);
  out.radiance = radiance->GetPointer(0);
  std::atomic<vtkIdType> firstWithoutNormal(n);
  vtkSMPTools::For(0, n, 1024, [&](vtkIdType begin, vtkIdType end) {
    const vtkIdType first = shadeRange(shading->kernel, out, begin, end);
    if (first < end) // else none in this range
    {
      slAtomicMinimum(firstWithoutNormal, first);
    }
  });
  if (this->ZeroNormalsAreErrors && firstWithoutNormal.load() < n)
  {
    return this->FailOnZeroNormal(output, firstWithoutNormal.load(), n);
  }

  vtkPointData* pd = output->GetPointData();
  for (vtkFloatArray* a : { ambient.Get(), diffuseOut.Get(), specular.Get(), emission.Get(), radiance.Get() })
  {
    pd->AddArray(a);
  }
  for (const auto& a : perLight)
  {
    pd->AddArray(a);
  }
  return 1;
}

void slRadianceFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PerLightArrays: " << this->PerLightArrays << "\n";
}
