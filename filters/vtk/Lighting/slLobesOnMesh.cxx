#include "slLobesOnMesh.h"

#include "slFiniteParameters.h"
#include "slFloat3View.h"
#include "slLightingSetup.h"
#include "slLobeGeometry.h"

#include "shadelab/LightingTables.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <memory>

vtkStandardNewMacro(slLobesOnMesh);
vtkCxxSetObjectMacro(slLobesOnMesh, PointIds, vtkIdList);

slLobesOnMesh::slLobesOnMesh() = default;

slLobesOnMesh::~slLobesOnMesh()
{
  this->SetPointIds(nullptr);
}

int slLobesOnMesh::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  using namespace shadelab;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->NumberOfLobesDrawn = 0;
  const std::string badParameter = slNonFiniteParameter({ { "Scale", this->Scale } });
  if (!badParameter.empty())
  {
    return this->Fail(output, badParameter);
  }
  LightingSetup setup;
  if (!this->PrepareLighting(input, output, true, setup))
  {
    return 0;
  }
  int light = this->LightIndex;
  if (light < 0)
  {
    for (size_t l = 0; l < setup.lights.size() && light < 0; ++l)
    {
      light = lightHasDirection(setup.lights[l].type) ? static_cast<int>(l) : -1;
    }
    if (light < 0)
    {
      return this->Fail(output, "scene: it has only ambient lights; a lobe needs an incident direction");
    }
  }
  if (light >= static_cast<int>(setup.lights.size()))
  {
    return this->Fail(output, "LightIndex " + std::to_string(light) + " is out of range: the scene has " +
        std::to_string(setup.lights.size()) + " lights");
  }
  if (!lightHasDirection(setup.lights[static_cast<size_t>(light)].type))
  {
    // An ambient light lights every point from no direction: without this
    // check every point would count as unlit and the output would be empty.
    return this->Fail(output, "LightIndex " + std::to_string(light) +
        ": the light is ambient; a lobe needs an incident direction (a directional, point or spot light)");
  }

  vtkDataArray* tangentArray = nullptr;
  if (!this->GetTangents(input, output, setup, tangentArray))
  {
    return 0;
  }
  const vtkIdType n = input->GetNumberOfPoints();
  const Float3View points(input->GetPoints()->GetData());
  const Float3View normals(input->GetPointData()->GetNormals());
  const auto tangents = tangentArray ? std::make_unique<Float3View>(tangentArray) : nullptr;
  const glsl::slLight& chosen = setup.lights[static_cast<size_t>(light)];
  // Lit: where f_r is not zero (slBRDF's own grazing limit), so a lobe shows.
  auto lit = [&](vtkIdType id) { return glsl::slCosTheta(chosen, points[id], normals[id]) > glsl::SL_MIN_COS_THETA; };
  std::vector<vtkIdType> ids;
  if (this->PointIds)
  {
    for (vtkIdType k = 0; k < this->PointIds->GetNumberOfIds(); ++k)
    {
      const vtkIdType id = this->PointIds->GetId(k);
      if (id < 0 || id >= n)
      {
        return this->Fail(output, "PointIds: point " + std::to_string(id) + " is not in the mesh (it has " +
            std::to_string(n) + " points)");
      }
      ids.push_back(id);
    }
  }
  else
  {
    // An even stride through the lit points, so that every sampled point shows a lobe.
    std::vector<vtkIdType> candidates;
    for (vtkIdType id = 0; id < n; ++id)
    {
      if (lit(id))
      {
        candidates.push_back(id);
      }
    }
    const size_t count = std::min(candidates.size(), static_cast<size_t>(this->NumberOfLobes));
    for (size_t k = 0; k < count; ++k)
    {
      ids.push_back(candidates[k * candidates.size() / count]);
    }
  }

  for (vtkIdType id : ids)
  {
    const glm::vec3 p = points[id];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    {
      return this->Fail(output, "input mesh: point " + std::to_string(id) + " has a coordinate that is not finite");
    }
  }
  this->NumberOfLobesDrawn = static_cast<int>(std::count_if(ids.begin(), ids.end(), lit));
  auto lobeAt = [&](vtkIdType id) {
    LobeSpec spec;
    spec.material = setup.material;
    spec.model = setup.model;
    spec.normal = normals[id];
    spec.tangent = tangents ? (*tangents)[id] : glm::vec3(0.0f);
    spec.origin = points[id];
    spec.toLight = glsl::slDirectionToLight(chosen, points[id]);
    spec.timesCosine = this->MultiplyByCosine;
    spec.thetaResolution = this->ThetaResolution;
    spec.phiResolution = this->PhiResolution;
    return spec;
  };

  // First pass: the largest r, so every lobe shares one scale.
  float largest = 0.0f;
  for (vtkIdType id : ids)
  {
    vtkNew<vtkPoints> p;
    vtkNew<vtkCellArray> c;
    vtkNew<vtkFloatArray> v;
    appendLobe(lobeAt(id), p, c, v);
    largest = std::max(largest, static_cast<float>(v->GetRange()[1]));
  }
  const double scale = largest > 0.0f ? this->Scale * input->GetLength() / largest : 0.0;

  vtkNew<vtkPoints> outPoints;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkFloatArray> values;
  values->SetName("BRDF");
  vtkNew<vtkIdTypeArray> owners;
  owners->SetName("PointId");
  for (vtkIdType id : ids)
  {
    LobeSpec spec = lobeAt(id);
    spec.scale = scale;
    appendLobe(spec, outPoints, polys, values);
    while (owners->GetNumberOfTuples() < values->GetNumberOfTuples())
    {
      owners->InsertNextValue(id);
    }
  }
  output->SetPoints(outPoints);
  output->SetPolys(polys);
  output->GetPointData()->SetScalars(values);
  output->GetPointData()->AddArray(owners);
  return 1;
}

void slLobesOnMesh::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightIndex: " << this->LightIndex << "\n";
  os << indent << "PointIds: " << this->PointIds << "\n";
  os << indent << "NumberOfLobes: " << this->NumberOfLobes << "\n";
  os << indent << "NumberOfLobesDrawn: " << this->NumberOfLobesDrawn << "\n";
  os << indent << "Scale: " << this->Scale << "\n";
  os << indent << "MultiplyByCosine: " << this->MultiplyByCosine << "\n";
  os << indent << "ThetaResolution: " << this->ThetaResolution << "\n";
  os << indent << "PhiResolution: " << this->PhiResolution << "\n";
}
