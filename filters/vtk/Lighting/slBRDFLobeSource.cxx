#include "slBRDFLobeSource.h"

#include "shadelab/SceneLimits.h"

#include "slLobeGeometry.h"
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

vtkStandardNewMacro(slBRDFLobeSource);

slBRDFLobeSource::slBRDFLobeSource()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
}

slBRDFLobeSource::~slBRDFLobeSource() = default;

int slBRDFLobeSource::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  using namespace shadelab;
  LobeSpec spec;
  spec.model = this->Model;
  spec.material.ambient = spec.material.emission = glm::vec3(0.0f);
  spec.material.diffuse = glm::vec3(static_cast<float>(this->DiffuseWeight));
  spec.material.specular = glm::vec3(static_cast<float>(this->SpecularWeight));
  spec.material.shininess = static_cast<float>(this->Shininess);
  const double theta = this->IncidenceAngle * 3.14159265358979323846 / 180.0;
  spec.toLight = glm::vec3(static_cast<float>(-std::sin(theta)), 0.0f, static_cast<float>(std::cos(theta)));
  spec.timesCosine = this->MultiplyByCosine;
  spec.thetaResolution = this->ThetaResolution;
  spec.phiResolution = this->PhiResolution;

  for (int port = 0; port < 2; ++port)
  {
    vtkPolyData* output = vtkPolyData::GetData(outputVector, port);
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> cells;
    vtkNew<vtkFloatArray> values;
    values->SetName("BRDF");
    if (port == 0)
    {
      appendLobe(spec, points, cells, values);
      output->SetPolys(cells);
    }
    else
    {
      appendSlice(spec, points, cells, values);
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

void slBRDFLobeSource::SetShininess(double shininess)
{
  const double clamped = std::clamp(shininess, 0.0, shadelab::kMaxShininess);
  if (this->Shininess != clamped)
  {
    this->Shininess = clamped;
    this->Modified();
  }
}

void slBRDFLobeSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Model: " << this->Model << "\n";
  os << indent << "Shininess: " << this->Shininess << "\n";
  os << indent << "DiffuseWeight: " << this->DiffuseWeight << "\n";
  os << indent << "SpecularWeight: " << this->SpecularWeight << "\n";
  os << indent << "IncidenceAngle: " << this->IncidenceAngle << "\n";
  os << indent << "MultiplyByCosine: " << this->MultiplyByCosine << "\n";
  os << indent << "ThetaResolution: " << this->ThetaResolution << "\n";
  os << indent << "PhiResolution: " << this->PhiResolution << "\n";
}
