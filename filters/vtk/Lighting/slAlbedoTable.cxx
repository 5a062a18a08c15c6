#include "slAlbedoTable.h"

#include "shadelab/Albedo.h"
#include "shadelab/Scene.h"

#include "slFiniteParameters.h"
#include "slMaterialNumbers.h"
#include "slModelCheck.h"

#include <vtkDoubleArray.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkSMPTools.h>
#include <vtkTable.h>

#include <vector>

vtkStandardNewMacro(slAlbedoTable);

slAlbedoTable::slAlbedoTable()
  : Material(new shadelab::SceneMaterial)
  , ModelEnabled(static_cast<size_t>(shadelab::kLightingModelCount), true)
{
  this->Material->shininess = 20.0f;
  this->SetNumberOfInputPorts(0);
}

slAlbedoTable::~slAlbedoTable() = default;

int slAlbedoTable::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  using namespace shadelab;
  vtkTable* output = vtkTable::GetData(outputVector);
  const std::string badParameter = slNonFiniteParameter({ { "MaximumIncidence", this->MaximumIncidence } });
  if (!badParameter.empty())
  {
    vtkErrorMacro(<< badParameter);
    return 0;
  }
  const int angles = this->NumberOfAngles;
  vtkNew<vtkDoubleArray> degrees;
  degrees->SetName("IncidenceDegrees");
  degrees->SetNumberOfTuples(angles);
  for (int a = 0; a < angles; ++a)
  {
    degrees->SetValue(a, this->MaximumIncidence * a / (angles - 1));
  }
  output->AddColumn(degrees);
  std::vector<int> models;
  for (int model = 0; model < kLightingModelCount; ++model)
  {
    if (this->ModelEnabled[static_cast<size_t>(model)])
    {
      models.push_back(model);
    }
  }
  const int count = static_cast<int>(models.size());
  std::vector<double> values(static_cast<size_t>(count * angles));
  const glsl::slMaterial material = toEvaluationMaterial(*this->Material);
  vtkSMPTools::For(0, count * angles, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType k = begin; k < end; ++k)
    {
      const int model = models[static_cast<size_t>(k / angles)], a = static_cast<int>(k % angles);
      glsl::slMaterial m = material;
      m.ambient = m.emission = glm::vec3(0.0f);
      // The diffuse albedo of a model without a specular term, else its specular one.
      const UnitWeights unit = unitWeights(static_cast<ShadingModel>(model));
      m.diffuse = glm::vec3(unit.diffuse);
      m.specular = glm::vec3(unit.specular);
      values[static_cast<size_t>(k)] =
        directionalAlbedo(model, m, degrees->GetValue(a) * 3.14159265358979323846 / 180.0);
    }
  });
  for (int i = 0; i < count; ++i)
  {
    vtkNew<vtkDoubleArray> column;
    column->SetName(modelName(static_cast<ShadingModel>(models[static_cast<size_t>(i)])));
    column->SetNumberOfTuples(angles);
    for (int a = 0; a < angles; ++a)
    {
      column->SetValue(a, values[static_cast<size_t>(i * angles + a)]);
    }
    output->AddColumn(column);
  }
  return 1;
}

SL_MATERIAL_NUMBER_METHODS(slAlbedoTable)

bool slAlbedoTable::SetModelEnabled(int model, bool enabled)
{
  if (!slCheckModel(this, model, false, "SetModelEnabled"))
  {
    return false;
  }
  if (this->ModelEnabled[static_cast<size_t>(model)] != enabled)
  {
    this->ModelEnabled[static_cast<size_t>(model)] = enabled;
    this->Modified();
  }
  return true;
}

bool slAlbedoTable::SetModelEnabled(const char* name, bool enabled)
{
  const int model = slModelNumber(name);
  return model < 0 ? slCheckModelName(this, name, "SetModelEnabled") : this->SetModelEnabled(model, enabled);
}

bool slAlbedoTable::GetModelEnabled(int model)
{
  return shadelab::isLightingModel(model) && this->ModelEnabled[static_cast<size_t>(model)];
}

void slAlbedoTable::EnableAllModels()
{
  for (int model = 0; model < shadelab::kLightingModelCount; ++model)
  {
    this->SetModelEnabled(model, true);
  }
}

void slAlbedoTable::DisableAllModels()
{
  for (int model = 0; model < shadelab::kLightingModelCount; ++model)
  {
    this->SetModelEnabled(model, false);
  }
}

void slAlbedoTable::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  slPrintMaterialNumbers(os, indent, *this->Material);
  os << indent << "NumberOfAngles: " << this->NumberOfAngles << "\n";
  os << indent << "MaximumIncidence: " << this->MaximumIncidence << "\n";
  os << indent << "Models:";
  for (int model = 0; model < shadelab::kLightingModelCount; ++model)
  {
    if (this->ModelEnabled[static_cast<size_t>(model)])
    {
      os << " " << shadelab::modelName(static_cast<shadelab::ShadingModel>(model));
    }
  }
  os << "\n";
}
