#include "slBRDFLobeSource.h"

#include "shadelab/Scene.h"

#include "slFiniteParameters.h"
#include "slLobeGeometry.h"
#include "slMaterialNumbers.h"
#include "slModelCheck.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(slBRDFLobeSource);

slBRDFLobeSource::slBRDFLobeSource()
  : Material(new shadelab::SceneMaterial)
{
  this->Material->shininess = 20.0f;
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
}

slBRDFLobeSource::~slBRDFLobeSource() = default;

namespace
{
/// The lobe's settings, with its @p material, as the geometry code takes them.
shadelab::LobeSpec lobeSpec(slBRDFLobeSource* source, const shadelab::SceneMaterial& material)
{
  using namespace shadelab;
  LobeSpec spec;
  spec.model = source->GetModel();
  spec.material = toEvaluationMaterial(material);
  spec.material.ambient = spec.material.emission = glm::vec3(0.0f);
  // A negative weight is the model's unit weight (unitWeights()).
  const UnitWeights unit = unitWeights(static_cast<ShadingModel>(spec.model));
  const double kd = source->GetDiffuseWeight(), ks = source->GetSpecularWeight();
  spec.material.diffuse = glm::vec3(kd < 0.0 ? unit.diffuse : static_cast<float>(kd));
  spec.material.specular = glm::vec3(ks < 0.0 ? unit.specular : static_cast<float>(ks));
  double toLight[3];
  source->GetDirectionToLight(toLight);
  spec.toLight = glm::vec3(glm::dvec3(toLight[0], toLight[1], toLight[2]));
  spec.timesCosine = source->GetMultiplyByCosine();
  spec.thetaResolution = source->GetThetaResolution();
  spec.phiResolution = source->GetPhiResolution();
  return spec;
}

void fillDirections(vtkFloatArray* array, const std::vector<glm::vec3>& directions)
{
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(static_cast<vtkIdType>(directions.size()));
  for (size_t k = 0; k < directions.size(); ++k)
  {
    array->SetTypedTuple(static_cast<vtkIdType>(k), &directions[k].x);
  }
}

/// @p array's tuples as RGB values, or an error line if it does not hold
/// one for each of @p count directions.
std::string readValues(vtkFloatArray* array, size_t count, const char* which, std::vector<glm::vec3>& values)
{
  if (array->GetNumberOfComponents() != 3 || static_cast<size_t>(array->GetNumberOfTuples()) != count)
  {
    return std::string("the ") + which + " BRDF values hold " + std::to_string(array->GetNumberOfTuples()) + " tuples of " +
      std::to_string(array->GetNumberOfComponents()) + " components; the lobe has " + std::to_string(count) +
      " directions (3 components each)";
  }
  values.resize(count);
  for (size_t k = 0; k < count; ++k)
  {
    array->GetTypedTuple(static_cast<vtkIdType>(k), &values[k].x);
  }
  return "";
}
} // namespace

void slBRDFLobeSource::GetDirectionToLight(double toLight[3])
{
  const double theta = this->IncidenceAngle * 3.14159265358979323846 / 180.0;
  toLight[0] = -std::sin(theta);
  toLight[1] = 0.0;
  toLight[2] = std::cos(theta);
}

void slBRDFLobeSource::ComputeOutgoingDirections(vtkFloatArray* surface, vtkFloatArray* slice)
{
  const shadelab::LobeSpec spec = lobeSpec(this, *this->Material);
  fillDirections(surface, shadelab::lobeDirections(spec));
  fillDirections(slice, shadelab::sliceDirections(spec));
}

void slBRDFLobeSource::SetBRDFValues(vtkFloatArray* surface, vtkFloatArray* slice)
{
  this->SurfaceBRDFValues = surface;
  this->SliceBRDFValues = slice;
  this->Modified();
}

vtkFloatArray* slBRDFLobeSource::GetSurfaceBRDFValues()
{
  return this->SurfaceBRDFValues;
}

vtkFloatArray* slBRDFLobeSource::GetSliceBRDFValues()
{
  return this->SliceBRDFValues;
}

int slBRDFLobeSource::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  using namespace shadelab;
  const std::string badParameter = slNonFiniteParameter({ { "DiffuseWeight", this->DiffuseWeight },
    { "SpecularWeight", this->SpecularWeight }, { "IncidenceAngle", this->IncidenceAngle } });
  if (!badParameter.empty())
  {
    vtkErrorMacro(<< badParameter);
    return 0;
  }
  const LobeSpec spec = lobeSpec(this, *this->Material);
  const bool given = this->SurfaceBRDFValues || this->SliceBRDFValues;
  std::vector<glm::vec3> surfaceValues, sliceValues;
  if (given)
  {
    std::string problem = !this->SurfaceBRDFValues || !this->SliceBRDFValues
      ? std::string("SetBRDFValues needs both arrays, the surface's and the slice's")
      : readValues(this->SurfaceBRDFValues, lobeDirections(spec).size(), "surface", surfaceValues);
    if (problem.empty())
    {
      problem = readValues(this->SliceBRDFValues, sliceDirections(spec).size(), "slice", sliceValues);
    }
    if (!problem.empty())
    {
      vtkErrorMacro(<< problem);
      return 0;
    }
  }

  for (int port = 0; port < 2; ++port)
  {
    vtkPolyData* output = vtkPolyData::GetData(outputVector, port);
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> cells;
    vtkNew<vtkFloatArray> values;
    values->SetName("BRDF");
    if (port == 0)
    {
      appendLobe(spec, points, cells, values, given ? &surfaceValues : nullptr);
      output->SetPolys(cells);
    }
    else
    {
      appendSlice(spec, points, cells, values, given ? &sliceValues : nullptr);
      output->SetLines(cells);
    }
    output->SetPoints(points);
    output->GetPointData()->SetScalars(values);
  }
  return 1;
}

void slBRDFLobeSource::SetModel(int model)
{
  if (slCheckModel(this, model) && model != this->Model)
  {
    this->Model = model;
    this->Modified();
  }
}

bool slBRDFLobeSource::SetModelName(const char* name)
{
  return slSetModelByName(this, name);
}

std::string slBRDFLobeSource::GetModelName() const
{
  return slModelNameOf(this->Model);
}

SL_MATERIAL_NUMBER_METHODS(slBRDFLobeSource)

void slBRDFLobeSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Model: " << this->Model << " (" << this->GetModelName() << ")\n";
  slPrintMaterialNumbers(os, indent, *this->Material);
  os << indent << "DiffuseWeight: " << this->DiffuseWeight << "\n";
  os << indent << "SpecularWeight: " << this->SpecularWeight << "\n";
  os << indent << "IncidenceAngle: " << this->IncidenceAngle << "\n";
  os << indent << "MultiplyByCosine: " << this->MultiplyByCosine << "\n";
  os << indent << "ThetaResolution: " << this->ThetaResolution << "\n";
  os << indent << "PhiResolution: " << this->PhiResolution << "\n";
  os << indent << "BRDFValues: " << (this->SurfaceBRDFValues ? "given" : "(the model's)") << "\n";
}
