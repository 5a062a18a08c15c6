#ifndef shadelab_tests_LightingTestMeshes_h
#define shadelab_tests_LightingTestMeshes_h
// Small meshes and scenes for the lighting filter tests, and helpers to read
// arrays back. Expected values are computed in the tests from first
// principles with <cmath>, never through the code under test.

#include "shadelab/Scene.h"
#include "AzimuthTangents.h"
#include "slScene.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>

#include <array>
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>

namespace shadelab
{
namespace test
{
constexpr double kPi = 3.14159265358979323846;

/// A UV sphere of radius 1 at the origin with point normals and tangents
/// (addAzimuthTangents()).
inline vtkSmartPointer<vtkPolyData> sphere(int resolution = 12)
{
  vtkNew<vtkSphereSource> source;
  source->SetRadius(1.0);
  source->SetThetaResolution(resolution);
  source->SetPhiResolution(resolution);
  source->Update();
  vtkSmartPointer<vtkPolyData> mesh = source->GetOutput();
  test::addAzimuthTangents(mesh);
  return mesh;
}

/// One vertex per given point/normal pair, with tangents (addAzimuthTangents()).
inline vtkSmartPointer<vtkPolyData> pointsWithNormals(const std::vector<std::array<double, 6>>& pn)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkCellArray> verts;
  for (const auto& v : pn)
  {
    const vtkIdType id = points->InsertNextPoint(v[0], v[1], v[2]);
    normals->InsertNextTuple3(v[3], v[4], v[5]);
    verts->InsertNextCell(1, &id);
  }
  mesh->SetPoints(points);
  mesh->SetVerts(verts);
  mesh->GetPointData()->SetNormals(normals);
  test::addAzimuthTangents(mesh);
  return mesh;
}

/// A white light (unit colours, no ambient part) of @p type.
inline SceneLight whiteLight(LightType type)
{
  SceneLight l;
  l.type = type;
  l.ambient = glm::vec3(0.0f);
  l.diffuse = glm::vec3(1.0f);
  l.specular = glm::vec3(1.0f);
  l.intensity = 1.0f;
  l.attenuation = glm::vec3(1.0f, 0.0f, 0.0f);
  return l;
}

/// A scene with @p lights, a fixed eye at @p eye and material k_a, k_d, k_s, k_e, n.
inline vtkSmartPointer<slScene> makeScene(const std::vector<SceneLight>& lights, ShadingModel model,
  const glm::vec3& eye = glm::vec3(0.0f, 0.0f, 10.0f))
{
  Scene s;
  s.lights = lights;
  s.model = model;
  s.camera.hasPosition = true;
  s.camera.position = eye;
  s.camera.focalPoint = glm::vec3(0.0f);
  s.material.ambient = glm::vec3(0.2f, 0.1f, 0.05f);
  s.material.diffuse = glm::vec3(0.8f, 0.5f, 0.25f);
  s.material.specular = glm::vec3(0.5f);
  s.material.emission = glm::vec3(0.01f, 0.02f, 0.03f);
  s.material.shininess = 20.0f;
  auto scene = vtkSmartPointer<slScene>::New();
  scene->SetScene(s);
  return scene;
}

inline std::array<double, 3> tuple3(vtkPolyData* mesh, const char* name, vtkIdType i)
{
  vtkDataArray* a = mesh->GetPointData()->GetArray(name);
  std::array<double, 3> v{ { NAN, NAN, NAN } };
  if (a && a->GetNumberOfComponents() == 3)
  {
    a->GetTuple(i, v.data());
  }
  return v;
}

/// True when every value of every point and cell array is finite, except
/// in the input arrays named in @p inputs (passed through as given).
inline bool allFinite(vtkPolyData* mesh, std::initializer_list<std::string> inputs = { "Normals" })
{
  for (vtkFieldData* data : { static_cast<vtkFieldData*>(mesh->GetPointData()),
         static_cast<vtkFieldData*>(mesh->GetCellData()) })
  {
    for (int a = 0; a < data->GetNumberOfArrays(); ++a)
    {
      vtkDataArray* array = data->GetArray(a);
      if (array && array->GetName() && std::find(inputs.begin(), inputs.end(), array->GetName()) != inputs.end())
      {
        continue;
      }
      for (vtkIdType i = 0; array && i < array->GetNumberOfValues(); ++i)
      {
        if (!std::isfinite(array->GetComponent(i / array->GetNumberOfComponents(), static_cast<int>(i % array->GetNumberOfComponents()))))
        {
          return false;
        }
      }
    }
  }
  return true;
}

} // namespace test
} // namespace shadelab

#endif
