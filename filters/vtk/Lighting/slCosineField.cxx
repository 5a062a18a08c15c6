#include "slCosineField.h"
#include "slCoreBoundary.h"

#include "slFloat3View.h"
#include "slLightingSetup.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolygon.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>

#include <vector>

vtkStandardNewMacro(slCosineField);

namespace
{
using shadelab::glsl::slLight;

vtkSmartPointer<vtkFloatArray> scalarArray(const std::string& name, vtkIdType n)
{
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetName(name.c_str());
  slSetNumberOfTuplesOrThrow(a, n);
  return a;
}

/// The unit normal of the triangle strip through @p ids: its triangles'
/// normals weighted by their areas (twice the area is the cross product's
/// length), every second triangle turned as the strip's order requires;
/// (0, 0, 0) for a strip of no area. Newell's method over the strip's points
/// in order would follow a self-crossing outline: 0 on a flat strip.
glm::dvec3 stripNormal(vtkPoints* points, const vtkIdType* ids, vtkIdType count)
{
  glm::dvec3 sum(0.0);
  for (vtkIdType i = 0; i + 2 < count; ++i)
  {
    glm::dvec3 p[3];
    for (int k = 0; k < 3; ++k)
    {
      points->GetPoint(ids[i + k], &p[k].x);
    }
    const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    sum += i % 2 == 0 ? n : -n;
  }
  const double length = glm::length(sum);
  return length > 0.0 ? sum / length : glm::dvec3(0.0);
}

/// Where and with which normal each cell is evaluated: its vertex centroid
/// and its normal (the input's cell normals, else Newell's polygon normal or
/// the strip's normal).
void cellFrames(vtkPolyData* mesh, std::vector<glm::vec3>& centres, std::vector<glm::vec3>& normals)
{
  const vtkIdType n = mesh->GetNumberOfCells();
  centres.assign(static_cast<size_t>(n), glm::vec3(0.0f));
  normals.assign(static_cast<size_t>(n), glm::vec3(0.0f));
  vtkDataArray* given = mesh->GetCellData()->GetNormals();
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < n; ++c)
  {
    mesh->GetCellPoints(c, ids);
    glm::dvec3 sum(0.0);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      double p[3];
      mesh->GetPoint(ids->GetId(k), p);
      sum += glm::dvec3(p[0], p[1], p[2]);
    }
    if (ids->GetNumberOfIds() > 0)
    {
      centres[static_cast<size_t>(c)] = glm::vec3(sum / static_cast<double>(ids->GetNumberOfIds()));
    }
    double normal[3] = { 0.0, 0.0, 0.0 };
    if (given && given->GetNumberOfComponents() == 3)
    {
      given->GetTuple(c, normal);
    }
    else if (mesh->GetCellType(c) == VTK_TRIANGLE_STRIP)
    {
      const glm::dvec3 n = stripNormal(mesh->GetPoints(), ids->GetPointer(0), ids->GetNumberOfIds());
      normal[0] = n.x;
      normal[1] = n.y;
      normal[2] = n.z;
    }
    else if (ids->GetNumberOfIds() >= 3 && mesh->GetCellType(c) != VTK_POLY_LINE && mesh->GetCellType(c) != VTK_POLY_VERTEX)
    {
      vtkPolygon::ComputeNormal(mesh->GetPoints(), static_cast<int>(ids->GetNumberOfIds()), ids->GetPointer(0), normal);
    }
    normals[static_cast<size_t>(c)] = glm::vec3(normal[0], normal[1], normal[2]);
  }
}

/// Clamped and raw cosines of one light over @p count positions/normals.
template <typename Position, typename Normal>
void cosines(const slLight& light, vtkIdType count, Position position, Normal normal, float* clamped, float* raw)
{
  using namespace shadelab::glsl;
  vtkSMPTools::For(0, count, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      const vec3 P = position(i);
      const vec3 N = normal(i);
      raw[i] = slCosTheta(light, P, N);
      clamped[i] = slDiffuseFactor(SL_MODEL_LAMBERT, slMaterial(), slSafeNormalize(N), slDirectionToLight(light, P), vec3(0.0f));
    }
  });
}
} // namespace

slCosineField::slCosineField() = default;
slCosineField::~slCosineField() = default;

int slCosineField::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  using namespace shadelab;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  LightingSetup setup;
  if (!this->PrepareLighting(input, output, true, setup))
  {
    return 0;
  }
  const int lightCount = static_cast<int>(setup.lights.size());
  if (this->LightIndex >= lightCount)
  {
    return this->Fail(output, "LightIndex " + std::to_string(this->LightIndex) + " is out of range: the scene has " +
        std::to_string(lightCount) + " lights");
  }
  output->ShallowCopy(input);
  const Float3View points(input->GetPoints()->GetData());
  const Float3View normals(input->GetPointData()->GetNormals());
  std::vector<glm::vec3> centres, cellNormals;
  if (this->ComputeCellArrays)
  {
    cellFrames(input, centres, cellNormals);
  }
  const int first = this->LightIndex < 0 ? 0 : this->LightIndex;
  const int last = this->LightIndex < 0 ? lightCount - 1 : this->LightIndex;
  for (int l = first; l <= last; ++l)
  {
    const std::string suffix = this->LightIndex < 0 ? "_" + std::to_string(l) : "";
    const glsl::slLight& light = setup.lights[static_cast<size_t>(l)];
    auto clamped = scalarArray("CosTheta" + suffix, input->GetNumberOfPoints());
    auto raw = scalarArray("CosThetaRaw" + suffix, input->GetNumberOfPoints());
    cosines(light, input->GetNumberOfPoints(), [&](vtkIdType i) { return points[i]; },
      [&](vtkIdType i) { return normals[i]; }, clamped->GetPointer(0), raw->GetPointer(0));
    output->GetPointData()->AddArray(clamped);
    output->GetPointData()->AddArray(raw);
    if (this->ComputeCellArrays)
    {
      auto cellClamped = scalarArray("CosTheta" + suffix, input->GetNumberOfCells());
      auto cellRaw = scalarArray("CosThetaRaw" + suffix, input->GetNumberOfCells());
      cosines(light, input->GetNumberOfCells(), [&](vtkIdType c) { return centres[static_cast<size_t>(c)]; },
        [&](vtkIdType c) { return cellNormals[static_cast<size_t>(c)]; }, cellClamped->GetPointer(0),
        cellRaw->GetPointer(0));
      output->GetCellData()->AddArray(cellClamped);
      output->GetCellData()->AddArray(cellRaw);
    }
  }
  return 1;
}

void slCosineField::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightIndex: " << this->LightIndex << "\n";
  os << indent << "ComputeCellArrays: " << this->ComputeCellArrays << "\n";
}
