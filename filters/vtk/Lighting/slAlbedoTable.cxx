#include "slAlbedoTable.h"

#include "shadelab/Albedo.h"
#include "shadelab/Scene.h"

#include "slFiniteParameters.h"
#include "slMaterialNumbers.h"

#include <vtkDoubleArray.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkSMPTools.h>
#include <vtkTable.h>

#include <vector>

vtkStandardNewMacro(slAlbedoTable);

slAlbedoTable::slAlbedoTable()
  : Material(new shadelab::SceneMaterial)
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
  const int models = static_cast<int>(modelNames().size());
  std::vector<double> values(static_cast<size_t>(models * angles));
  const glsl::slMaterial material = toEvaluationMaterial(*this->Material);
  vtkSMPTools::For(0, models * angles, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType k = begin; k < end; ++k)
    {
      const int model = static_cast<int>(k / angles), a = static_cast<int>(k % angles);
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
  for (int model = 0; model < models; ++model)
  {
    vtkNew<vtkDoubleArray> column;
    column->SetName(modelNames()[static_cast<size_t>(model)].c_str());
    column->SetNumberOfTuples(angles);
    for (int a = 0; a < angles; ++a)
    {
      column->SetValue(a, values[static_cast<size_t>(model * angles + a)]);
    }
    output->AddColumn(column);
  }
  return 1;
}

SL_MATERIAL_NUMBER_METHODS(slAlbedoTable)

void slAlbedoTable::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  slPrintMaterialNumbers(os, indent, *this->Material);
  os << indent << "NumberOfAngles: " << this->NumberOfAngles << "\n";
  os << indent << "MaximumIncidence: " << this->MaximumIncidence << "\n";
}
