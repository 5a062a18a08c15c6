// slRadianceFilter against the lighting equation evaluated by hand.
#include "LightingTestMeshes.h"

#include "shadelab/ShadePoint.h"
#include "slRadianceFilter.h"
#include "VTKErrors.h"

#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <random>

using namespace shadelab;
using namespace shadelab::test;

namespace
{
vtkSmartPointer<vtkPolyData> run(slRadianceFilter* filter, vtkPolyData* mesh)
{
  filter->SetInputData(mesh);
  EXPECT_EQ(updateError(filter), "");
  return filter->GetOutput();
}
} // namespace

TEST(RadianceFilter, LambertDiffuseIsKdTimesCosine)
{
  // Directional light from 60 degrees off the normal: diffuse = I k_d cos 60.
  SceneLight light = whiteLight(LightType::Directional);
  const double theta = 60.0 * kPi / 180.0;
  light.direction = -glm::vec3(std::sin(theta), 0.0, std::cos(theta));
  light.intensity = 2.0f;
  vtkNew<slRadianceFilter> filter;
  filter->SetScene(makeScene({ light }, ShadingModel::Lambert));
  vtkPolyData* out = run(filter, pointsWithNormals({ { 0, 0, 0, 0, 0, 1 }, { 1, 0, 0, 0, 0, -1 } }));
  const auto d = tuple3(out, "Diffuse", 0);
  EXPECT_NEAR(d[0], 2.0 * 0.8 * 0.5, 1e-6);
  EXPECT_NEAR(d[1], 2.0 * 0.5 * 0.5, 1e-6);
  EXPECT_NEAR(d[2], 2.0 * 0.25 * 0.5, 1e-6);
  EXPECT_EQ(tuple3(out, "Specular", 0)[0], 0.0);
  // Facing away: no diffuse, never negative.
  EXPECT_EQ(tuple3(out, "Diffuse", 1)[0], 0.0);
  // Emission is k_e, and Radiance the sum of the four terms.
  for (vtkIdType i = 0; i < 2; ++i)
  {
    EXPECT_NEAR(tuple3(out, "Emission", i)[2], 0.03, 1e-7);
    for (int c = 0; c < 3; ++c)
    {
      const double sum = tuple3(out, "Ambient", i)[c] + tuple3(out, "Diffuse", i)[c] + tuple3(out, "Specular", i)[c] +
        tuple3(out, "Emission", i)[c];
      EXPECT_NEAR(tuple3(out, "Radiance", i)[c], sum, 1e-6);
    }
  }
}

TEST(RadianceFilter, BlinnPhongPointLightWithAttenuation)
{
  // Point light at (1, 0, 2), eye at (-1, 0, 3), surface point at the origin, N = +z.
  SceneLight light = whiteLight(LightType::Point);
  light.position = glm::vec3(1.0f, 0.0f, 2.0f);
  light.attenuation = glm::vec3(0.5f, 0.25f, 0.125f);
  light.ambient = glm::vec3(0.5f);
  vtkNew<slRadianceFilter> filter;
  filter->SetScene(makeScene({ light }, ShadingModel::BlinnPhong, glm::vec3(-1.0f, 0.0f, 3.0f)));
  vtkPolyData* out = run(filter, pointsWithNormals({ { 0, 0, 0, 0, 0, 1 } }));
  const double d = std::sqrt(5.0);
  const double att = std::min(1.0, 1.0 / (0.5 + 0.25 * d + 0.125 * d * d));
  const double L[3] = { 1 / d, 0, 2 / d };
  const double dv = std::sqrt(10.0);
  const double V[3] = { -1 / dv, 0, 3 / dv };
  double H[3] = { L[0] + V[0], L[1] + V[1], L[2] + V[2] };
  const double hl = std::sqrt(H[0] * H[0] + H[1] * H[1] + H[2] * H[2]);
  const double spec = std::pow(H[2] / hl, 20.0);
  EXPECT_NEAR(tuple3(out, "Diffuse", 0)[0], att * L[2] * 0.8, 1e-6);
  EXPECT_NEAR(tuple3(out, "Specular", 0)[0], att * spec * 0.5, 1e-5);
  EXPECT_NEAR(tuple3(out, "Ambient", 0)[1], att * 0.5 * 0.1, 1e-7);
}

TEST(RadianceFilter, VectorizedLoopAgreesWithShadePointForEveryModelAndLightType)
{
  // The filter's vectorised loop against the lighting core's exact scalar
  // slShadeLight() on a sphere under a directional, a point, a spot (smooth
  // edge) and an ambient light, for every model: every output term, and each
  // light's own array. The lights have their own colours and intensities and
  // the points a base colour, since the loop multiplies those once per light
  // and once per point rather than where slShadeLight does. Whole and
  // fractional shininess and spot exponents, since the loop's pow squares
  // for whole exponents and uses exp2(y log2 x) otherwise.
  SceneLight directional = whiteLight(LightType::Directional);
  directional.direction = glm::vec3(-0.3f, -0.5f, -1.0f);
  directional.diffuse = glm::vec3(1.0f, 0.6f, 0.3f);
  directional.ambient = glm::vec3(0.1f, 0.2f, 0.3f);
  directional.intensity = 0.7f;
  SceneLight point = whiteLight(LightType::Point);
  point.position = glm::vec3(2.0f, 1.0f, 1.5f);
  point.attenuation = glm::vec3(0.2f, 0.3f, 0.1f);
  point.specular = glm::vec3(0.4f, 0.9f, 0.6f);
  point.intensity = 1.3f;
  SceneLight spot = whiteLight(LightType::Spot);
  spot.position = glm::vec3(0.0f, 0.0f, 3.0f);
  spot.direction = glm::vec3(0.1f, 0.0f, -1.0f);
  spot.cutoffDegrees = 25.0f;
  spot.edgeDegrees = 5.0f;
  spot.exponent = 3.0f;
  spot.diffuse = glm::vec3(0.5f, 1.0f, 0.8f);
  spot.intensity = 0.9f;
  SceneLight ambient = whiteLight(LightType::Ambient);
  ambient.ambient = glm::vec3(0.3f, 0.25f, 0.2f);
  ambient.intensity = 0.6f;
  vtkSmartPointer<vtkPolyData> mesh = sphere(20);
  vtkNew<vtkFloatArray> base;
  base->SetName("Base");
  base->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    base->InsertNextTuple3(0.2 + 0.8 * (i % 7) / 6.0, 1.0 - 0.5 * (i % 3) / 2.0, 0.5 + 0.5 * (i % 2));
  }
  mesh->GetPointData()->AddArray(base);
  // Tangents for the anisotropic models: not unit, not orthogonal to the
  // normal, with a handedness (the lighting orthonormalises and ignores it).
  vtkNew<vtkFloatArray> tangents;
  tangents->SetName("Tangents");
  tangents->SetNumberOfComponents(4);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    tangents->InsertNextTuple4(-2.0 * p[1], 2.0 * p[0], 0.3, (i % 2) ? 1.0 : -1.0);
  }
  mesh->GetPointData()->AddArray(tangents);
  const glm::vec3 eye(1, 2, 5);
  const char* terms[] = { "Ambient", "Diffuse", "Specular", "Radiance" };
  for (int variant = 0; variant < 2 * kLightingModelCount; ++variant)
  {
    const int model = variant % kLightingModelCount;
    const float fraction = variant < kLightingModelCount ? 0.0f : 0.5f;
    spot.exponent = 3.0f + fraction;
    vtkSmartPointer<slScene> scene =
      makeScene({ directional, point, spot, ambient }, static_cast<ShadingModel>(model), eye);
    Scene withShininess = scene->GetScene();
    withShininess.material.shininess = 20.0f + fraction;
    scene->SetScene(withShininess);
    vtkNew<slRadianceFilter> filter;
    filter->SetScene(scene);
    filter->SetDiffuseColorArrayName("Base");
    filter->PerLightArraysOn();
    vtkPolyData* out = run(filter, mesh);
    std::vector<glsl::slLight> lights;
    for (const SceneLight& l : scene->GetScene().lights)
    {
      lights.push_back(toEvaluationLight(l));
    }
    double worst = 0.0;
    auto compare = [&worst](const std::array<double, 3>& got, const glm::vec3& expected) {
      for (int c = 0; c < 3; ++c)
      {
        const double error = std::abs(got[c] - expected[c]) / std::max(1e-3, double(std::abs(expected[c])));
        // NaN (an output value, or tuple3's answer for a missing array) counts as infinitely wrong.
        worst = std::isnan(error) ? INFINITY : std::max(worst, error);
      }
    };
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      double p[3], n[3], b[3], t[4];
      mesh->GetPoint(i, p);
      mesh->GetPointData()->GetNormals()->GetTuple(i, n);
      tangents->GetTuple(i, t);
      base->GetTuple(i, b);
      glsl::slMaterial m = toEvaluationMaterial(scene->GetScene().material);
      m.ambient *= glm::vec3(b[0], b[1], b[2]);
      m.diffuse *= glm::vec3(b[0], b[1], b[2]);
      const glm::vec3 P(p[0], p[1], p[2]), N(n[0], n[1], n[2]), T(t[0], t[1], t[2]);
      const glsl::slTerms expected = shadePoint(lights, m, model, P, N, eye, T);
      const glm::vec3 values[] = { expected.ambient, expected.diffuse, expected.specular, glsl::slTotal(expected) };
      for (int t = 0; t < 4; ++t)
      {
        compare(tuple3(out, terms[t], i), values[t]);
      }
      for (size_t l = 0; l < lights.size(); ++l)
      {
        const std::string name = "Radiance_" + std::to_string(l);
        compare(tuple3(out, name.c_str(), i), glsl::slTotal(glsl::slShadeLight(lights[l], m, model, P, N, T, eye)));
      }
    }
    EXPECT_LT(worst, 1e-4) << "model " << model << ", shininess " << withShininess.material.shininess;
  }
}

TEST(RadianceFilter, PerLightArraysSumToTheLitPart)
{
  SceneLight a = whiteLight(LightType::Directional);
  a.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  SceneLight b = whiteLight(LightType::Point);
  b.position = glm::vec3(0.0f, 3.0f, 0.0f);
  vtkNew<slRadianceFilter> filter;
  filter->SetScene(makeScene({ a, b }, ShadingModel::Phong));
  filter->PerLightArraysOn();
  vtkPolyData* out = run(filter, sphere());
  ASSERT_NE(out->GetPointData()->GetArray("Radiance_1"), nullptr);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(tuple3(out, "Radiance_0", i)[c] + tuple3(out, "Radiance_1", i)[c] + tuple3(out, "Emission", i)[c],
        tuple3(out, "Radiance", i)[c], 1e-5);
    }
  }
}

TEST(RadianceFilter, TakesVTKLightsPropertyAndCamera)
{
  // A VTK scene light shining straight down -z onto N = +z; a property with
  // diffuse 0.5 x (1, 0.5, 0.25) and ambient 0.2 x white; VTK's implicit
  // white ambient light adds k_a.
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(false);
  light->SetPosition(0, 0, 1);
  light->SetFocalPoint(0, 0, 0);
  light->SetIntensity(0.5);
  light->SetAmbientColor(0, 0, 0);
  vtkNew<vtkLightCollection> lights;
  lights->AddItem(light);
  vtkNew<vtkProperty> property;
  property->SetDiffuse(0.5);
  property->SetDiffuseColor(1.0, 0.5, 0.25);
  property->SetAmbient(0.2);
  property->SetAmbientColor(1.0, 1.0, 1.0);
  property->SetSpecular(0.0);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0, 0, 5);
  vtkNew<slRadianceFilter> filter;
  filter->SetLights(lights);
  filter->SetProperty(property);
  filter->SetCamera(camera);
  vtkPolyData* out = run(filter, pointsWithNormals({ { 0, 0, 0, 0, 0, 1 } }));
  EXPECT_NEAR(tuple3(out, "Diffuse", 0)[0], 0.5 * 0.5 * 1.0, 1e-6);
  EXPECT_NEAR(tuple3(out, "Diffuse", 0)[2], 0.5 * 0.5 * 0.25, 1e-6);
  EXPECT_NEAR(tuple3(out, "Ambient", 0)[1], 0.2, 1e-6);

  // A light of the collection dimmed, then moved to 60 degrees off the
  // normal: the filter runs again (the collection's own time stays).
  light->SetIntensity(0.25);
  ASSERT_EQ(updateError(filter), "");
  EXPECT_NEAR(tuple3(filter->GetOutput(), "Diffuse", 0)[0], 0.5 * 0.25 * 1.0, 1e-6);
  light->SetPosition(std::sqrt(3.0), 0, 1);
  ASSERT_EQ(updateError(filter), "");
  EXPECT_NEAR(tuple3(filter->GetOutput(), "Diffuse", 0)[0], 0.5 * 0.25 * 0.5, 1e-6);
}

TEST(RadianceFilter, DiffuseFromColourArrayAndTexture)
{
  SceneLight light = whiteLight(LightType::Directional);
  light.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  light.ambient = glm::vec3(1.0f); // so that Ambient = k_a times the base colour
  vtkSmartPointer<vtkPolyData> mesh = pointsWithNormals({ { 0, 0, 0, 0, 0, 1 }, { 1, 0, 0, 0, 0, 1 } });
  vtkNew<vtkFloatArray> colours;
  colours->SetName("Colour");
  colours->SetNumberOfComponents(3);
  colours->InsertNextTuple3(0.25, 0.5, 1.0);
  colours->InsertNextTuple3(1.0, 0.0, 0.0);
  mesh->GetPointData()->AddArray(colours);
  vtkNew<vtkUnsignedCharArray> bytes;
  bytes->SetName("Bytes");
  bytes->SetNumberOfComponents(4);
  bytes->InsertNextTuple4(255, 188, 0, 255); // used as given: 188 means 188/255, as on the GPU
  bytes->InsertNextTuple4(0, 0, 0, 255);
  mesh->GetPointData()->AddArray(bytes);
  vtkNew<slRadianceFilter> filter;
  filter->SetScene(makeScene({ light }, ShadingModel::Lambert));
  filter->SetDiffuseColorArrayName("Colour");
  vtkPolyData* out = run(filter, mesh);
  // The colour is a base colour: it multiplies the material's k_d = (0.8, 0.5,
  // 0.25) and k_a, as scalar colours do in the render pass.
  const glm::vec3 kd(0.8f, 0.5f, 0.25f);
  EXPECT_NEAR(tuple3(out, "Diffuse", 0)[1], kd.y * 0.5, 1e-6);
  EXPECT_NEAR(tuple3(out, "Diffuse", 0)[2], kd.z * 1.0, 1e-6);
  EXPECT_NEAR(tuple3(out, "Diffuse", 1)[0], kd.x * 1.0, 1e-6);
  EXPECT_EQ(tuple3(out, "Diffuse", 1)[1], 0.0);
  EXPECT_NEAR(tuple3(out, "Ambient", 0)[1], 0.1 * 0.5, 1e-6); // k_a = (0.2, 0.1, 0.05)
  EXPECT_NEAR(tuple3(out, "Ambient", 0)[2], 0.05 * 1.0, 1e-6);
  EXPECT_EQ(tuple3(out, "Ambient", 1)[2], 0.0);
  EXPECT_NE(out->GetPointData()->GetArray("Colour"), nullptr) << "input arrays pass through";
  filter->SetDiffuseColorArrayName("Bytes");
  out = run(filter, mesh);
  EXPECT_NEAR(tuple3(out, "Diffuse", 0)[0], kd.x, 1e-6);
  EXPECT_NEAR(tuple3(out, "Diffuse", 0)[1], kd.y * 188.0 / 255.0, 1e-6);
  EXPECT_EQ(tuple3(out, "Diffuse", 1)[0], 0.0);

  // A 2 x 1 texture: left texel red, right texel blue; u = 0.25 and 0.75 hit their centres.
  vtkNew<vtkImageData> texture;
  texture->SetDimensions(2, 1, 1);
  vtkNew<vtkFloatArray> pixels;
  pixels->SetNumberOfComponents(3);
  pixels->InsertNextTuple3(1, 0, 0);
  pixels->InsertNextTuple3(0, 0, 1);
  texture->GetPointData()->SetScalars(pixels);
  vtkNew<vtkFloatArray> uv;
  uv->SetNumberOfComponents(2);
  uv->InsertNextTuple2(0.25, 0.5);
  uv->InsertNextTuple2(0.75, 0.5);
  mesh->GetPointData()->SetTCoords(uv);
  filter->SetDiffuseColorArrayName(nullptr);
  filter->SetDiffuseTexture(texture);
  out = run(filter, mesh);
  EXPECT_NEAR(tuple3(out, "Diffuse", 0)[0], kd.x, 1e-6);
  EXPECT_NEAR(tuple3(out, "Diffuse", 0)[2], 0.0, 1e-6);
  EXPECT_NEAR(tuple3(out, "Diffuse", 1)[2], kd.z, 1e-6);
}
