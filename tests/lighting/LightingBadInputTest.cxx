// Bad input to the lighting filters: one-line errors, empty outputs, and
// never a NaN in any output array (degenerate meshes).
#include "LightingTestMeshes.h"

#include "slCosineField.h"
#include "slRadianceFilter.h"

#include "shadelab/SceneLimits.h"
#include "VTKErrors.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkPointData.h>
#include <vtkProperty.h>

#include <gtest/gtest.h>

#include <limits>
#include <random>

using namespace shadelab;
using namespace shadelab::test;

namespace
{
SceneLight someLight()
{
  SceneLight l = whiteLight(LightType::Point);
  l.position = glm::vec3(1.0f, 1.0f, 1.0f);
  return l;
}

/// Degenerate geometry: a zero normal, a NaN normal, an infinite normal, a
/// point at the light's position, a point at the eye, coincident points.
vtkSmartPointer<vtkPolyData> degenerateMesh()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  return pointsWithNormals({ { 0, 0, 0, 0, 0, 0 }, { 0, 0, 0, nan, 0, 1 }, { 0, 0, 0, inf, 0, 0 },
    { 1, 1, 1, 0, 0, 1 }, { 0, 0, 10, 0, 0, 1 }, { 0.5, 0.5, 0.5, 1e-30, 0, 0 } });
}

template <typename Filter>
void expectError(vtkPolyData* mesh, vtkSmartPointer<slScene> scene, const std::string& message)
{
  vtkNew<Filter> filter;
  filter->SetScene(scene);
  filter->SetInputData(mesh);
  EXPECT_EQ(updateError(filter), message);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
}
} // namespace

TEST(LightingBadInput, EmptyMesh)
{
  vtkNew<vtkPolyData> empty;
  expectError<slRadianceFilter>(empty, makeScene({ someLight() }, ShadingModel::Phong), "input mesh: it is empty (no points)");
  expectError<slCosineField>(empty, makeScene({ someLight() }, ShadingModel::Phong), "input mesh: it is empty (no points)");
}

TEST(LightingBadInput, NoNormals)
{
  vtkSmartPointer<vtkPolyData> mesh = sphere(6);
  mesh->GetPointData()->SetNormals(nullptr);
  expectError<slRadianceFilter>(mesh, makeScene({ someLight() }, ShadingModel::Phong),
    "input mesh: it has no point normals; compute them first (slPolyDataNormals)");

  // An array named "Normals" that is not the attribute is not used: the
  // message says why, rather than that there is none.
  vtkNew<vtkFloatArray> named;
  named->SetName("Normals");
  named->SetNumberOfComponents(3);
  named->SetNumberOfTuples(mesh->GetNumberOfPoints());
  named->FillValue(1.0f);
  mesh->GetPointData()->AddArray(named);
  expectError<slCosineField>(mesh, makeScene({ someLight() }, ShadingModel::Phong),
    "input mesh: its point array \"Normals\" is not set as its point normals (vtkPointData::SetNormals)");
}

TEST(LightingBadInput, ShortNormals)
{
  // Fewer normals than points: read beyond the array before (slCosineField
  // crashed on a large mesh); point and cell normals alike.
  vtkSmartPointer<vtkPolyData> mesh = sphere(6);
  mesh->GetPointData()->GetNormals()->SetNumberOfTuples(3);
  const std::string message =
    "input mesh: point array \"Normals\" has 3 tuples for " + std::to_string(mesh->GetNumberOfPoints()) + " points";
  expectError<slRadianceFilter>(mesh, makeScene({ someLight() }, ShadingModel::Phong), message);
  expectError<slCosineField>(mesh, makeScene({ someLight() }, ShadingModel::Phong), message);

  mesh = sphere(6);
  vtkNew<vtkFloatArray> cellNormals;
  cellNormals->SetName("CellNormals");
  cellNormals->SetNumberOfComponents(3);
  cellNormals->SetNumberOfTuples(1);
  cellNormals->FillValue(1.0f);
  mesh->GetCellData()->SetNormals(cellNormals);
  expectError<slCosineField>(mesh, makeScene({ someLight() }, ShadingModel::Phong),
    "input mesh: cell array \"CellNormals\" has 1 tuple for " + std::to_string(mesh->GetNumberOfCells()) + " cells");
}

TEST(LightingBadInput, ZeroLengthNormal)
{
  expectError<slRadianceFilter>(degenerateMesh(), makeScene({ someLight() }, ShadingModel::Phong),
    "input mesh: point 0 of 6 has a zero-length or non-finite normal (ZeroNormalsAreErrors is on)");
  expectError<slCosineField>(degenerateMesh(), makeScene({ someLight() }, ShadingModel::Phong),
    "input mesh: point 0 of 6 has a zero-length or non-finite normal (ZeroNormalsAreErrors is on)");
}

TEST(LightingBadInput, FirstNormalWithoutDirectionOfALargeMesh)
{
  // slRadianceFilter finds these while it shades, in parallel ranges, and
  // slCosineField before it starts, in parallel blocks: the error names the
  // first bad point of the mesh, whichever range finds one first, and a mesh
  // without one shades without error whatever its ranges.
  vtkSmartPointer<vtkPolyData> mesh = sphere(400);
  const vtkIdType n = mesh->GetNumberOfPoints();
  ASSERT_GT(n, 100000);
  vtkSmartPointer<slScene> scene = makeScene({ someLight() }, ShadingModel::BlinnPhong);
  {
    vtkNew<slRadianceFilter> filter;
    filter->SetScene(scene);
    filter->SetInputData(mesh);
    EXPECT_EQ(updateError(filter), "");
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), n);
  }
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  normals->SetTuple3(n - 1, 0.0, 0.0, 0.0);
  normals->SetTuple3(n / 2 + 3, nan, 0.0, 1.0);
  normals->SetTuple3(n / 3 + 25, 0.0, 0.0, 0.0); // a later one near it: same range, maybe same block
  normals->SetTuple3(n / 3 + 5, 1e30, 0.0, 0.0); // too long to square in float
  const std::string message = "input mesh: point " + std::to_string(n / 3 + 5) + " of " + std::to_string(n) +
    " has a zero-length or non-finite normal (ZeroNormalsAreErrors is on)";
  expectError<slRadianceFilter>(mesh, scene, message);
  // The other lighting filters check in slLitFilter, by blocks of points.
  expectError<slCosineField>(mesh, scene, message);
}

TEST(LightingBadInput, TinyNormalsGetTheSameAnswerFromEveryFilter)
{
  // A normal of length 5e-20 has no direction (below SL_TINY_LENGTH = 1e-18,
  // where its square is subnormal and the SIMD estimate takes it for 0): the
  // radiance filter (which checks while it shades) and the cosine field
  // (which checks first) both say so. One of length 1e-17 is a direction
  // for both, lit like a unit normal.
  vtkSmartPointer<slScene> scene = makeScene({ someLight() }, ShadingModel::Lambert);
  const std::string message =
    "input mesh: point 0 of 2 has a zero-length or non-finite normal (ZeroNormalsAreErrors is on)";
  expectError<slRadianceFilter>(pointsWithNormals({ { 0, 0, 0, 5e-20, 0, 0 }, { 1, 0, 0, 0, 0, 1 } }), scene, message);
  expectError<slCosineField>(pointsWithNormals({ { 0, 0, 0, 5e-20, 0, 0 }, { 1, 0, 0, 0, 0, 1 } }), scene, message);
  vtkSmartPointer<vtkPolyData> mesh = pointsWithNormals({ { 0, 0, 0, 0, 0, 1e-17 }, { 0, 0, 0, 0, 0, 1 } });
  vtkNew<slRadianceFilter> radiance;
  radiance->SetScene(scene);
  radiance->SetInputData(mesh);
  EXPECT_EQ(updateError(radiance), "");
  EXPECT_GT(tuple3(radiance->GetOutput(), "Diffuse", 1)[0], 0.0);
  EXPECT_NEAR(tuple3(radiance->GetOutput(), "Diffuse", 0)[0], tuple3(radiance->GetOutput(), "Diffuse", 1)[0], 1e-6);
  vtkNew<slCosineField> cosine;
  cosine->SetScene(scene);
  cosine->SetInputData(mesh);
  EXPECT_EQ(updateError(cosine), "");
}

TEST(LightingBadInput, NoLight)
{
  expectError<slRadianceFilter>(sphere(6), makeScene({}, ShadingModel::Phong), "scene: it has no lights");
  expectError<slCosineField>(sphere(6), makeScene({}, ShadingModel::Phong), "scene: it has no lights");
}

TEST(LightingBadInput, DegenerateMeshGivesNoNaN)
{
  // A spot light at a point of the mesh: L is zero there. (A spot of zero
  // direction is a scene error of its own, tests/core/SceneLimitsTest.cxx.)
  SceneLight spot = whiteLight(LightType::Spot);
  spot.position = glm::vec3(0.0f);
  spot.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  SceneLight ambient = whiteLight(LightType::Ambient);
  ambient.ambient = glm::vec3(1.0f);
  for (int model = 0; model < kLightingModelCount; ++model)
  {
    vtkSmartPointer<slScene> scene =
      makeScene({ someLight(), spot, ambient }, static_cast<ShadingModel>(model), glm::vec3(0.0f, 0.0f, 10.0f));
    vtkNew<slRadianceFilter> radiance;
    radiance->SetScene(scene);
    radiance->ZeroNormalsAreErrorsOff();
    radiance->PerLightArraysOn();
    radiance->SetInputData(degenerateMesh());
    EXPECT_EQ(updateError(radiance), "");
    EXPECT_TRUE(allFinite(radiance->GetOutput())) << model;
    // A zero normal gets ambient and emission only.
    EXPECT_NEAR(tuple3(radiance->GetOutput(), "Diffuse", 0)[0], 0.0, 0.0);
    EXPECT_GT(tuple3(radiance->GetOutput(), "Ambient", 0)[0], 0.0);

    vtkNew<slCosineField> cosine;
    cosine->SetScene(scene);
    cosine->ZeroNormalsAreErrorsOff();
    cosine->SetInputData(degenerateMesh());
    EXPECT_EQ(updateError(cosine), "");
    EXPECT_TRUE(allFinite(cosine->GetOutput())) << model;
  }
}

TEST(LightingBadInput, EyeSeeingTheLightThroughTheSurfaceGivesNoInfinity)
{
  // Points on the segment from the eye to a point light, lit from the far
  // side (N.L > 0, N.V < 0): L is nearly -V, |L + V| is rounding noise, and
  // Blinn-Phong's (N.L + N.V) / |L + V| could reach 16 here, whose 40th power
  // overflows. N.H is clamped to 1 (slSpecularFactor), so the lecture
  // models' specular term stays at most k_s times the light's colour.
  const glm::vec3 eye(-2.0f, -3.5f, 0.75f), lightAt(1.25f, 1.25f, 1.0f);
  SceneLight light = whiteLight(LightType::Point);
  light.position = lightAt;
  std::vector<std::array<double, 6>> points{ { -0.578125, -1.421875, 0.859375, 0.3225, 0.5386, -0.7784 } };
  std::mt19937 random(3);
  std::normal_distribution<double> gaussian;
  for (int k = 1; k < 256; ++k)
  {
    const glm::dvec3 P = glm::dvec3(eye) + (k / 256.0) * glm::dvec3(lightAt - eye);
    glm::dvec3 N(gaussian(random), gaussian(random), gaussian(random));
    if (glm::dot(N, glm::dvec3(lightAt) - P) < 0.0)
    {
      N = -N;
    }
    points.push_back({ P.x, P.y, P.z, N.x, N.y, N.z });
  }
  vtkSmartPointer<vtkPolyData> mesh = pointsWithNormals(points);
  for (float shininess : { 40.0f, 1024.0f, 40.5f })
  {
    for (int model = 0; model < kLightingModelCount; ++model)
    {
      vtkSmartPointer<slScene> scene = makeScene({ light }, static_cast<ShadingModel>(model), eye);
      Scene s = scene->GetScene();
      s.material.shininess = shininess;
      scene->SetScene(s);
      vtkNew<slRadianceFilter> radiance;
      radiance->SetScene(scene);
      radiance->SetInputData(mesh);
      ASSERT_EQ(updateError(radiance), "");
      EXPECT_TRUE(allFinite(radiance->GetOutput())) << "model " << model << ", shininess " << shininess;
      if (model == static_cast<int>(ShadingModel::Phong) || model == static_cast<int>(ShadingModel::BlinnPhong))
      {
        for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
        {
          EXPECT_LE(tuple3(radiance->GetOutput(), "Specular", i)[0], s.material.specular.x * (1.0 + 1e-6))
            << "point " << i << ", model " << model << ", shininess " << shininess;
        }
      }
    }
  }
}

TEST(LightingBadInput, ValuesAtTheSceneLimitsGiveFiniteTerms)
{
  // Every colour, intensity and coefficient at kMaxColourValue, shininess at
  // kMaxShininess, 8 lights of each kind: the largest terms a valid scene can
  // produce must still be finite (SceneLimits.h's reason for its limits).
  const float big = static_cast<float>(kMaxColourValue);
  std::vector<SceneLight> lights;
  for (const LightTypeInfo& info : kLightTypes)
  {
    const LightType type = info.type;
    for (int k = 0; k < 2; ++k)
    {
      SceneLight l = whiteLight(type);
      l.position = glm::vec3(0.2f * k, 0.1f, 2.0f);
      l.direction = glm::vec3(0.0f, 0.0f, -1.0f);
      l.ambient = l.diffuse = l.specular = glm::vec3(big);
      l.intensity = big;
      l.attenuation = glm::vec3(0.0f);
      lights.push_back(l);
    }
  }
  for (int model = 0; model < kLightingModelCount; ++model)
  {
    vtkSmartPointer<slScene> scene = makeScene(lights, static_cast<ShadingModel>(model), glm::vec3(0.0f, 0.0f, 5.0f));
    Scene s = scene->GetScene();
    s.material.ambient = s.material.diffuse = s.material.specular = s.material.emission = glm::vec3(big);
    s.material.shininess = static_cast<float>(kMaxShininess);
    // The microfacet models' sharpest lobes, one anisotropic pair at both
    // ends, and the largest index of refraction.
    s.material.roughness = s.material.roughnessX = 0.0f;
    s.material.roughnessY = 1.0f;
    s.material.ior = 10.0f;
    scene->SetScene(s);
    vtkNew<slRadianceFilter> radiance;
    radiance->SetScene(scene);
    radiance->PerLightArraysOn();
    radiance->SetInputData(sphere(24));
    ASSERT_EQ(updateError(radiance), "") << model;
    EXPECT_TRUE(allFinite(radiance->GetOutput())) << "model " << model;
    // Not vacuous: point 0 (the pole, facing the lights) reaches the
    // largest terms, specular included (the diffuse-only models have none).
    if (modelInfo(static_cast<ShadingModel>(model)).reads & kReadsSpecular)
    {
      EXPECT_GT(tuple3(radiance->GetOutput(), "Specular", 0)[0], 1e12) << model;
    }
  }
}

TEST(LightingBadInput, VTKLightsAndPropertiesAreCheckedLikeSceneFiles)
{
  // A VTK user's lights and property bypass the scene file reader: a NaN or
  // out-of-range value is a one-line error naming it, not NaN output.
  vtkNew<vtkLightCollection> lights;
  vtkNew<vtkLight> light;
  light->SetPosition(1.0, 1.0, 1.0);
  light->SetIntensity(std::numeric_limits<double>::quiet_NaN());
  lights->AddItem(light);
  vtkNew<slRadianceFilter> radiance;
  radiance->SetLights(lights);
  radiance->SetInputData(sphere(8));
  EXPECT_EQ(updateError(radiance),
    "scene (with the VTK lights, property or camera): lights[1] (\"VTK light 0\").intensity: nan is not a finite "
    "number");
  EXPECT_EQ(radiance->GetOutput()->GetNumberOfPoints(), 0);

  light->SetIntensity(1.0);
  vtkNew<vtkProperty> property;
  property->SetSpecularPower(std::numeric_limits<double>::quiet_NaN());
  radiance->SetProperty(property);
  EXPECT_EQ(updateError(radiance),
    "scene (with the VTK lights, property or camera): material.shininess: nan is not a finite number");
  property->SetSpecularPower(20.0);
  property->SetDiffuseColor(1.0, 2e6, 1.0);
  EXPECT_EQ(updateError(radiance),
    "scene (with the VTK lights, property or camera): material.diffuse[1]: 2e+06 is out of range [0, 1e+06]");
  property->SetDiffuseColor(1.0, 1.0, 1.0);
  EXPECT_EQ(updateError(radiance), "");
  EXPECT_TRUE(allFinite(radiance->GetOutput()));
}

TEST(LightingBadInput, ColourValuesBeyondTheLimitsAndTextureCoordinatesThatAreNotFinite)
{
  // A double colour array beyond float's range is clamped to
  // kMaxColourValue, not turned into infinity (then NaN next to a zero
  // colour); a point whose texture coordinates are NaN or infinite gets
  // colour 0, like a colour value that is not finite.
  vtkNew<slRadianceFilter> radiance;
  // Four copies of one point, so only the colour differs.
  vtkSmartPointer<vtkPolyData> mesh =
    pointsWithNormals({ { 0, 0, 0, 0, 0, 1 }, { 0, 0, 0, 0, 0, 1 }, { 0, 0, 0, 0, 0, 1 }, { 0, 0, 0, 0, 0, 1 } });
  vtkNew<vtkDoubleArray> colours;
  colours->SetName("C");
  colours->SetNumberOfComponents(3);
  colours->InsertNextTuple3(1e300, 0.0, 0.5);
  colours->InsertNextTuple3(-1e300, 1.0, 0.5);
  colours->InsertNextTuple3(std::numeric_limits<double>::quiet_NaN(), 1.0, 0.5);
  colours->InsertNextTuple3(0.5, 0.5, 0.5);
  mesh->GetPointData()->AddArray(colours);
  radiance->SetScene(makeScene({ someLight() }, ShadingModel::Phong, glm::vec3(0.0f, 0.0f, 10.0f)));
  radiance->SetDiffuseColorArrayName("C");
  radiance->SetInputData(mesh);
  ASSERT_EQ(updateError(radiance), "");
  EXPECT_TRUE(allFinite(radiance->GetOutput(), { "Normals", "C" })); // the input array "C" keeps its NaN
  const double diffuse0 = tuple3(radiance->GetOutput(), "Diffuse", 0)[0];
  const double diffuse3 = tuple3(radiance->GetOutput(), "Diffuse", 3)[0];
  EXPECT_NEAR(diffuse0 / diffuse3, kMaxColourValue / 0.5, kMaxColourValue * 1e-5);
  const double diffuse1 = tuple3(radiance->GetOutput(), "Diffuse", 1)[0];
  EXPECT_NEAR(diffuse1 / diffuse3, -kMaxColourValue / 0.5, kMaxColourValue * 1e-5); // negative: clamped to -1e6
  EXPECT_EQ(tuple3(radiance->GetOutput(), "Diffuse", 2)[0], 0.0);  // NaN counts as 0

  vtkNew<vtkImageData> texture;
  texture->SetDimensions(1, 1, 1);
  vtkNew<vtkFloatArray> pixels;
  pixels->SetNumberOfComponents(3);
  pixels->InsertNextTuple3(1, 1, 1);
  texture->GetPointData()->SetScalars(pixels);
  vtkNew<vtkDoubleArray> uv;
  uv->SetName("UV");
  uv->SetNumberOfComponents(2);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  uv->InsertNextTuple2(nan, 0.5);
  uv->InsertNextTuple2(0.5, inf);
  uv->InsertNextTuple2(-inf, nan);
  uv->InsertNextTuple2(0.5, 0.5);
  mesh->GetPointData()->SetTCoords(uv);
  radiance->SetDiffuseColorArrayName(nullptr);
  radiance->SetDiffuseTexture(texture);
  ASSERT_EQ(updateError(radiance), "");
  EXPECT_TRUE(allFinite(radiance->GetOutput(), { "Normals", "C", "UV" }));
  for (vtkIdType i = 0; i < 3; ++i)
  {
    EXPECT_EQ(tuple3(radiance->GetOutput(), "Diffuse", i)[0], 0.0) << i;
  }
  EXPECT_GT(tuple3(radiance->GetOutput(), "Diffuse", 3)[0], 0.0);
}

TEST(LightingBadInput, CellNamingAMissingPoint)
{
  // A polydata built in memory whose last triangle names a point beyond the
  // mesh: every lighting filter checks the cells before following them.
  vtkSmartPointer<vtkPolyData> mesh = sphere(6);
  const vtkIdType points = mesh->GetNumberOfPoints();
  vtkNew<vtkCellArray> polys;
  polys->DeepCopy(mesh->GetPolys());
  const vtkIdType bad[3] = { 0, 1, points + 5 };
  polys->InsertNextCell(3, bad);
  mesh->SetPolys(polys);
  const std::string message = "input mesh: polygon " + std::to_string(polys->GetNumberOfCells() - 1) +
    " names point " + std::to_string(points + 5) + ", but the mesh has " + std::to_string(points) + " points (0 to " +
    std::to_string(points - 1) + ")";
  expectError<slRadianceFilter>(mesh, makeScene({ someLight() }, ShadingModel::Phong), message);
  expectError<slCosineField>(mesh, makeScene({ someLight() }, ShadingModel::Phong), message);
}
