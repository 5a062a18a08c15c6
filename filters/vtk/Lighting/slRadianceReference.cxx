#include "slRadianceReference.h"

#include "shadelab/LightingTables.h"
#include "shadelab/RadianceEstimator.h"
#include "slCoreBoundary.h"
#include "slEnvironmentLoader.h"
#include "slFiniteParameters.h"
#include "slLightingSetup.h"
#include "slRadianceKernel.h"
#include "slShadingInputs.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(slRadianceReference);
vtkCxxSetObjectMacro(slRadianceReference, EnvironmentMap, vtkImageData);

namespace
{
void addSummary(vtkFieldData* field, const char* name, const glm::dvec3& v)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(3);
  a->InsertNextTuple3(v.x, v.y, v.z);
  field->AddArray(a);
}

/// The material at a point of base colour @p base: k_a and k_d multiplied by
/// it. f_r is k_d times a factor that does not read k_d plus the specular
/// lobe (slBRDF()), so this colours the reference as slWithBaseColour()
/// colours the discrete diffuse and ambient terms.
shadelab::glsl::slMaterial withBaseColour(shadelab::glsl::slMaterial m, const float* base)
{
  const glm::vec3 b(base[0], base[1], base[2]);
  m.ambient *= b;
  m.diffuse *= b;
  return m;
}
} // namespace

slRadianceReference::slRadianceReference() = default;

slRadianceReference::~slRadianceReference()
{
  this->SetEnvironmentFileName(nullptr);
  this->SetEnvironmentMap(nullptr);
}

vtkMTimeType slRadianceReference::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->EnvironmentMap && this->EnvironmentMap->GetMTime() > t)
  {
    t = this->EnvironmentMap->GetMTime();
  }
  return t;
}

int slRadianceReference::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  using namespace shadelab;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const std::string badParameter = slNonFiniteParameter({ { "EnvironmentScale", this->EnvironmentScale },
    { "LightRadius", this->LightRadius }, { "DirectionalLightAngle", this->DirectionalLightAngle } });
  if (!badParameter.empty())
  {
    return this->Fail(output, badParameter);
  }
  LightingSetup setup;
  if (!this->PrepareLighting(input, output, false, setup))
  {
    return 0;
  }
  shadelab::EnvironmentMap environment;
  const bool haveEnvironment = slRunCore(this, output, [&] {
    if (this->EnvironmentFileName && *this->EnvironmentFileName)
    {
      environmentFromFile(this->EnvironmentFileName, environment);
    }
    else if (this->EnvironmentMap)
    {
      environmentFromImage(this->EnvironmentMap, "EnvironmentMap", environment);
    }
  });
  if (!haveEnvironment)
  {
    return 0;
  }
  const bool anyLight = std::any_of(setup.lights.begin(), setup.lights.end(),
    [](const glsl::slLight& l) { return lightHasDirection(l.type); });
  if (environment.empty() && !(this->UseSceneLights && anyLight))
  {
    return this->Fail(output, "no light for the reference: give an environment map or a scene with (non-ambient) lights");
  }

  // The whole input's diagonal (over all MPI ranks), as vtkDataSet::GetLength().
  const double* b = this->WholeBounds;
  const double wholeDiagonal =
    std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
  ReferenceSetup reference;
  reference.lights = setup.lights;
  reference.useLights = this->UseSceneLights;
  reference.lightRadius =
    static_cast<float>(this->LightRadius > 0.0 ? this->LightRadius : 0.01 * wholeDiagonal);
  reference.directionalAngularRadius = static_cast<float>(this->DirectionalLightAngle * 3.14159265358979323846 / 180.0);
  reference.environment = environment.empty() ? nullptr : &environment;
  reference.environmentScale = static_cast<float>(this->EnvironmentScale);
  reference.material = setup.material;
  reference.model = setup.model;
  reference.strategy = static_cast<SamplingStrategy>(this->Strategy);
  reference.samples = this->SamplesPerPoint;
  reference.seed = static_cast<std::uint64_t>(static_cast<std::uint32_t>(this->Seed));

  const auto shading = this->PrepareShading(input, output, setup);
  if (!shading)
  {
    return 0;
  }
  const vtkIdType n = input->GetNumberOfPoints();
  auto radiance = rgbArray("Radiance", n), stdError = rgbArray("RadianceStdError", n);
  auto discrete = rgbArray("DiscreteRadiance", n), error = rgbArray("RadianceError", n);
  auto ambient = rgbArray("Ambient", n), diffuse = rgbArray("Diffuse", n), specular = rgbArray("Specular", n),
       emission = rgbArray("Emission", n);

  // The discrete lighting equation, as slRadianceFilter evaluates it.
  const RadianceKernelInput& in = shading->kernel;
  RadianceKernelOutput out;
  out.ambient = ambient->GetPointer(0);
  out.diffuse = diffuse->GetPointer(0);
  out.specular = specular->GetPointer(0);
  out.emission = emission->GetPointer(0);
  out.radiance = discrete->GetPointer(0);
  vtkSMPTools::For(0, n, 1024, [&](vtkIdType begin, vtkIdType end) { shadeRange(in, out, begin, end); });

  // The reference, in batches so that progress can be reported from this thread.
  float* r = radiance->GetPointer(0);
  float* s = stdError->GetPointer(0);
  const vtkIdType batches = std::min<vtkIdType>(n, 50);
  for (vtkIdType b = 0; b < batches; ++b)
  {
    vtkSMPTools::For(b * n / batches, (b + 1) * n / batches, [&](vtkIdType begin, vtkIdType end) {
      // This range's own copy, whose material takes each point's base colour.
      ReferenceSetup atPoint = reference;
      for (vtkIdType i = begin; i < end; ++i)
      {
        if (in.baseColour)
        {
          atPoint.material = withBaseColour(reference.material, in.baseColour + 3 * i);
        }
        const RadianceEstimate e =
          estimateRadiance(atPoint, shading->points[i], shading->normals[i],
            shading->tangents ? (*shading->tangents)[i] : glm::vec3(0.0f), setup.eye, static_cast<std::uint64_t>(i));
        for (int c = 0; c < 3; ++c)
        {
          r[3 * i + c] = std::isfinite(e.mean[c]) ? e.mean[c] : 0.0f;
          s[3 * i + c] = std::isfinite(e.stdError[c]) ? e.stdError[c] : 0.0f;
        }
      }
    });
    this->UpdateProgress(static_cast<double>(b + 1) / batches);
    if (this->GetAbortExecute())
    {
      return this->Fail(output, "aborted");
    }
  }

  glm::dvec3 sum(0.0), sumSquares(0.0), maxAbs(0.0), sumStdError(0.0);
  const float* d = discrete->GetPointer(0);
  float* e = error->GetPointer(0);
  for (vtkIdType i = 0; i < 3 * n; ++i)
  {
    e[i] = r[i] - d[i];
    const int c = static_cast<int>(i % 3);
    sum[c] += e[i];
    sumSquares[c] += static_cast<double>(e[i]) * e[i];
    maxAbs[c] = std::max(maxAbs[c], static_cast<double>(std::abs(e[i])));
    sumStdError[c] += s[i];
  }
  vtkPointData* pd = output->GetPointData();
  for (vtkFloatArray* a : { radiance.Get(), stdError.Get(), discrete.Get(), error.Get() })
  {
    pd->AddArray(a);
  }
  vtkFieldData* field = output->GetFieldData();
  addSummary(field, "RadianceErrorMean", sum / static_cast<double>(n));
  addSummary(field, "RadianceErrorRMS", glm::sqrt(sumSquares / static_cast<double>(n)));
  addSummary(field, "RadianceErrorMaxAbs", maxAbs);
  addSummary(field, "MeanStdError", sumStdError / static_cast<double>(n));
  return 1;
}

void slRadianceReference::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Strategy: " << this->Strategy << "\n";
  os << indent << "SamplesPerPoint: " << this->SamplesPerPoint << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "EnvironmentFileName: " << (this->EnvironmentFileName ? this->EnvironmentFileName : "(none)") << "\n";
  os << indent << "EnvironmentMap: " << this->EnvironmentMap << "\n";
  os << indent << "EnvironmentScale: " << this->EnvironmentScale << "\n";
  os << indent << "UseSceneLights: " << this->UseSceneLights << "\n";
  os << indent << "LightRadius: " << this->LightRadius << "\n";
  os << indent << "DirectionalLightAngle: " << this->DirectionalLightAngle << "\n";
}
