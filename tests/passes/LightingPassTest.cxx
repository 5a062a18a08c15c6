// slLightingPass: agreement with the CPU, the differences between flat,
// Gouraud and Phong, component views, and parameter updates.
#include "AzimuthTangents.h"
#include "PassTestUtilities.h"

#include "shadelab/LightingGLSL.h"
#include "shadelab/Scene.h"
#include "slLightingPass.h"
#include "slRadianceFilter.h"
#include "slScene.h"

#include <vtkActor.h>
#include <vtkImageData.h>
#include <vtkMapper.h>
#include <vtkTexture.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

using passtest::Image;

namespace
{
const glm::vec3 kMagenta(1.0f, 0.0f, 1.0f); // a background no lit grey surface reaches

vtkSmartPointer<vtkPolyData> sphere(int resolution)
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(resolution);
  source->SetPhiResolution(resolution);
  source->SetRadius(1.0);
  vtkNew<vtkPolyDataNormals> normals; // point and cell normals, no splitting
  normals->SetInputConnection(source->GetOutputPort());
  normals->SplittingOff();
  normals->ComputeCellNormalsOn();
  normals->Update();
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  shadelab::test::addAzimuthTangents(out); // for the anisotropic models
  return out;
}

/// Every light type, colours kept below saturation.
shadelab::Scene sphereScene(shadelab::ShadingModel model)
{
  shadelab::Scene s;
  s.model = model;
  s.frequency = shadelab::ShadingFrequency::Gouraud;
  s.background = kMagenta;
  s.camera.hasPosition = true;
  s.camera.position = glm::vec3(0.3f, 0.5f, 4.0f);
  s.camera.focalPoint = glm::vec3(0.0f);
  s.material.ambient = glm::vec3(0.3f);
  s.material.diffuse = glm::vec3(0.45f, 0.4f, 0.35f);
  s.material.specular = glm::vec3(0.25f);
  s.material.emission = glm::vec3(0.02f, 0.0f, 0.03f);
  s.material.shininess = 20.0f;

  shadelab::SceneLight key;
  key.direction = glm::vec3(-0.4f, -0.5f, -1.0f);
  key.diffuse = glm::vec3(0.8f);
  key.specular = glm::vec3(0.6f);
  s.lights.push_back(key);

  shadelab::SceneLight point;
  point.type = shadelab::LightType::Point;
  point.position = glm::vec3(2.0f, 1.0f, 1.5f);
  point.attenuation = glm::vec3(0.5f, 0.0f, 0.1f);
  point.diffuse = glm::vec3(0.3f, 0.2f, 0.1f);
  point.specular = glm::vec3(0.2f);
  point.ambient = glm::vec3(0.05f);
  s.lights.push_back(point);

  shadelab::SceneLight spot;
  spot.type = shadelab::LightType::Spot;
  spot.space = shadelab::LightSpace::Camera;
  spot.position = glm::vec3(0.0f, 1.0f, 1.0f);
  spot.direction = glm::vec3(0.0f, -1.0f, -1.0f);
  spot.cutoffDegrees = 40.0f;
  spot.edgeDegrees = 10.0f;
  spot.exponent = 2.0f;
  spot.diffuse = glm::vec3(0.1f, 0.2f, 0.3f);
  spot.specular = glm::vec3(0.1f);
  s.lights.push_back(spot);

  shadelab::SceneLight ambient;
  ambient.type = shadelab::LightType::Ambient;
  ambient.ambient = glm::vec3(0.15f);
  ambient.diffuse = ambient.specular = glm::vec3(0.0f);
  s.lights.push_back(ambient);
  if (model >= shadelab::ShadingModel::LambertNormalized)
  {
    // Normalised BRDFs divide by pi: give the lights irradiance pi for
    // comparable brightness (see docs/lighting-core.md).
    for (shadelab::SceneLight& l : s.lights)
    {
      l.intensity = l.type == shadelab::LightType::Ambient ? 1.0f : glm::pi<float>();
    }
    s.material.diffuse *= 0.8f;
    s.material.specular *= 0.3f; // (n+2)/2 = 11 times brighter highlights: stay unsaturated
  }
  return s;
}

/// The square [-h, h]^2 on z = 0 facing +z, one quad (two triangles once
/// drawn), with point normals.
vtkSmartPointer<vtkPolyData> facingSquare(double h)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-h, -h, 0);
  plane->SetPoint1(h, -h, 0);
  plane->SetPoint2(-h, h, 0);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(plane->GetOutputPort());
  normals->Update();
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  return out;
}

float maxChannelDifference(const Image& a, const Image& b, int x, int y)
{
  const float* p = a.at(x, y);
  const float* q = b.at(x, y);
  return std::max({ std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2]) });
}
} // namespace

class GouraudAgreesWithCPU : public ::testing::TestWithParam<int>
{
};

TEST_P(GouraudAgreesWithCPU, Within2Of255OnInteriorPixels)
{
  // (a) the pass in Gouraud mode; (b) the lighting core evaluated per vertex
  // on the CPU and drawn unlit as vertex colours. Same mesh, camera, window.
  const shadelab::Scene scene = sphereScene(static_cast<shadelab::ShadingModel>(GetParam()));
  vtkSmartPointer<vtkPolyData> mesh = sphere(48);
  passtest::Stage gpu = passtest::litStage(mesh, scene, 240, 240);
  const Image lit = gpu.render();

  vtkSmartPointer<vtkPolyData> coloured = vtkSmartPointer<vtkPolyData>::New();
  coloured->DeepCopy(mesh);
  passtest::colourPointsOnCPU(coloured, scene);
  passtest::Stage cpu = passtest::unlitStage(coloured, scene, 240, 240, false);
  const Image reference = cpu.render();

  const passtest::Agreement a = passtest::agreement(lit, reference, passtest::interiorMask(reference, kMagenta));
  ASSERT_GT(a.covered, 20000) << "the sphere should cover much of the window";
  EXPECT_GE(static_cast<double>(a.agreeing) / a.covered, 0.995)
    << "model " << shadelab::modelName(scene.model) << ": worst difference " << a.worst * 255.0f << "/255";
}

INSTANTIATE_TEST_SUITE_P(EveryModel, GouraudAgreesWithCPU, ::testing::Range(0, shadelab::kLightingModelCount),
  [](const ::testing::TestParamInfo<int>& info) {
    std::string name = shadelab::modelName(static_cast<shadelab::ShadingModel>(info.param));
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
  });

TEST(PhongMode, PixelAtAVertexMatchesTheCPU)
{
  // A finely divided plane facing the camera; a point light above it.
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1, -1, 0);
  plane->SetPoint1(1, -1, 0);
  plane->SetPoint2(-1, 1, 0);
  plane->SetResolution(40, 40);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(plane->GetOutputPort());
  normals->Update();
  vtkPolyData* mesh = normals->GetOutput();

  shadelab::Scene scene = sphereScene(shadelab::ShadingModel::BlinnPhong);
  scene.frequency = shadelab::ShadingFrequency::Phong;
  scene.camera.position = glm::vec3(0.0f, 0.0f, 3.0f);
  scene.lights.erase(scene.lights.begin() + 2); // keep the plane inside no spot edge
  passtest::Stage gpu = passtest::litStage(mesh, scene, 300, 300);
  const Image image = gpu.render();

  vtkSmartPointer<vtkPolyData> coloured = vtkSmartPointer<vtkPolyData>::New();
  coloured->DeepCopy(mesh);
  passtest::colourPointsOnCPU(coloured, scene);
  vtkUnsignedCharArray* cpu = vtkUnsignedCharArray::SafeDownCast(coloured->GetPointData()->GetScalars());
  int checked = 0;
  for (vtkIdType id = 0; id < mesh->GetNumberOfPoints(); id += 11)
  {
    double p[3], d[2];
    mesh->GetPoint(id, p);
    if (std::abs(p[0]) > 0.6 || std::abs(p[1]) > 0.6) // the view shows about +-0.8
    {
      continue;
    }
    gpu.toDisplay(p, d);
    // Display coordinates put pixel centres at half-integers.
    const int x = static_cast<int>(std::floor(d[0])), y = static_cast<int>(std::floor(d[1]));
    ASSERT_TRUE(x >= 0 && y >= 0 && x < image.width && y < image.height) << x << "," << y;
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(image.at(x, y)[c] * 255.0f, cpu->GetValue(3 * id + c), 2.0) << "vertex " << id << " channel " << c;
    }
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

TEST(ModeDifferences, PhongShowsAHighlightInsideACoarseQuadAndGouraudDoesNot)
{
  // Two triangles, 4 m across; a point light just above the centre. The
  // highlight falls between the vertices: only per-pixel lighting sees it.
  vtkSmartPointer<vtkPolyData> square = facingSquare(2.0);

  shadelab::Scene scene;
  scene.background = kMagenta;
  scene.model = shadelab::ShadingModel::BlinnPhong;
  scene.camera.hasPosition = true;
  scene.camera.position = glm::vec3(0.0f, 0.0f, 8.0f);
  scene.material.ambient = glm::vec3(0.0f);
  scene.material.diffuse = glm::vec3(0.2f);
  scene.material.specular = glm::vec3(0.8f);
  scene.material.shininess = 60.0f;
  shadelab::SceneLight light;
  light.type = shadelab::LightType::Point;
  light.position = glm::vec3(0.0f, 0.0f, 0.5f);
  scene.lights.push_back(light);

  auto renderAs = [&](shadelab::ShadingFrequency frequency) {
    scene.frequency = frequency;
    return passtest::litStage(square, scene, 200, 200).render();
  };
  const Image phong = renderAs(shadelab::ShadingFrequency::Phong);
  const Image gouraud = renderAs(shadelab::ShadingFrequency::Gouraud);

  // Centre of the window = centre of the quad; corners of the quad project
  // to about (13, 13) .. (187, 187) at this distance.
  const float phongCentre = phong.luminance(100, 100);
  const float gouraudCentre = gouraud.luminance(100, 100);
  const float phongNearCorner = phong.luminance(20, 20);
  const float gouraudNearCorner = gouraud.luminance(20, 20);
  EXPECT_GT(phongCentre, 0.8f) << "Phong lights the pixel under the light: a highlight";
  EXPECT_GT(phongCentre, phongNearCorner + 0.5f);
  // Gouraud interpolates the vertex colours: its centre cannot outshine them.
  float gouraudMax = 0.0f;
  for (int y = 15; y < 185; ++y)
  {
    for (int x = 15; x < 185; ++x)
    {
      gouraudMax = std::max(gouraudMax, gouraud.luminance(x, y));
    }
  }
  EXPECT_LT(gouraudCentre, 0.25f);
  EXPECT_LT(gouraudMax, phongCentre - 0.5f);
  EXPECT_NEAR(gouraudCentre, gouraudNearCorner, 0.1f);
}

TEST(ModeDifferences, FlatGivesOneColourPerFace)
{
  vtkSmartPointer<vtkPolyData> mesh = sphere(10);
  shadelab::Scene scene = sphereScene(shadelab::ShadingModel::Phong);
  scene.frequency = shadelab::ShadingFrequency::Flat;
  const Image flat = passtest::litStage(mesh, scene, 240, 240).render();

  // Which face covers each pixel: draw each face in its own colour, unlit.
  vtkSmartPointer<vtkPolyData> ids = vtkSmartPointer<vtkPolyData>::New();
  ids->DeepCopy(mesh);
  vtkNew<vtkUnsignedCharArray> faceColours;
  faceColours->SetNumberOfComponents(3);
  for (vtkIdType c = 0; c < ids->GetNumberOfCells(); ++c)
  {
    const unsigned char rgb[3] = { static_cast<unsigned char>(c % 250), static_cast<unsigned char>(c / 250), 200 };
    faceColours->InsertNextTypedTuple(rgb);
  }
  ids->GetPointData()->SetScalars(nullptr);
  ids->GetCellData()->SetScalars(faceColours);
  const Image faces = passtest::unlitStage(ids, scene, 240, 240, true).render();

  const std::vector<bool> mask = passtest::interiorMask(faces, kMagenta);
  std::map<int, std::pair<glm::vec3, glm::vec3>> range; // face -> (min, max) colour
  for (int y = 1; y + 1 < faces.height; ++y)
  {
    for (int x = 1; x + 1 < faces.width; ++x)
    {
      const float* f = faces.at(x, y);
      bool sameFaceAround = mask[static_cast<size_t>(y) * faces.width + x];
      for (int d = -1; d <= 1 && sameFaceAround; d += 2)
      {
        sameFaceAround = faces.at(x + d, y)[0] == f[0] && faces.at(x + d, y)[1] == f[1] &&
          faces.at(x, y + d)[0] == f[0] && faces.at(x, y + d)[1] == f[1];
      }
      if (!sameFaceAround)
      {
        continue;
      }
      const int face = static_cast<int>(std::lround(f[0] * 255.0f)) + 250 * static_cast<int>(std::lround(f[1] * 255.0f));
      const glm::vec3 colour(flat.at(x, y)[0], flat.at(x, y)[1], flat.at(x, y)[2]);
      auto it = range.find(face);
      if (it == range.end())
      {
        range[face] = { colour, colour };
      }
      else
      {
        it->second.first = glm::min(it->second.first, colour);
        it->second.second = glm::max(it->second.second, colour);
      }
    }
  }
  ASSERT_GT(range.size(), 40u) << "many faces visible";
  for (const auto& face : range)
  {
    const glm::vec3 spread = face.second.second - face.second.first;
    EXPECT_EQ(std::max({ spread.x, spread.y, spread.z }), 0.0f) << "face " << face.first;
  }
}

TEST(ModeDifferences, FineSphereConverges)
{
  // On a finely tessellated sphere flat, Gouraud and Phong all approach the
  // same picture. Tolerance: mean difference under 1/255 and 99% of interior
  // pixels within 4/255 (flat keeps a faint facet pattern in the highlight).
  vtkSmartPointer<vtkPolyData> mesh = sphere(256);
  shadelab::Scene scene = sphereScene(shadelab::ShadingModel::BlinnPhong);
  scene.material.shininess = 8.0f;
  std::vector<Image> images;
  for (auto f : { shadelab::ShadingFrequency::Flat, shadelab::ShadingFrequency::Gouraud,
         shadelab::ShadingFrequency::Phong })
  {
    scene.frequency = f;
    images.push_back(passtest::litStage(mesh, scene, 240, 240).render());
  }
  const std::vector<bool> mask = passtest::interiorMask(images[2], kMagenta);
  for (int a = 0; a < 2; ++a)
  {
    double sum = 0.0;
    long count = 0, within = 0;
    for (int y = 0; y < 240; ++y)
    {
      for (int x = 0; x < 240; ++x)
      {
        if (!mask[static_cast<size_t>(y) * 240 + x])
        {
          continue;
        }
        const float d = maxChannelDifference(images[static_cast<size_t>(a)], images[2], x, y);
        sum += d;
        ++count;
        within += d <= 4.0f / 255.0f + 1e-6f;
      }
    }
    EXPECT_LT(sum / count * 255.0, 1.0) << (a == 0 ? "flat" : "gouraud") << " vs phong";
    EXPECT_GE(static_cast<double>(within) / count, 0.99) << (a == 0 ? "flat" : "gouraud") << " vs phong";
  }
}

TEST(ComponentViews, TermsAddUpToTheTotal)
{
  vtkSmartPointer<vtkPolyData> mesh = sphere(64);
  shadelab::Scene scene = sphereScene(shadelab::ShadingModel::Phong);
  scene.frequency = shadelab::ShadingFrequency::Phong;
  passtest::Stage stage = passtest::litStage(mesh, scene, 160, 160);
  const Image total = stage.render();
  std::vector<Image> parts;
  for (int component = slLightingPass::AMBIENT; component <= slLightingPass::EMISSION; ++component)
  {
    stage.pass->SetComponent(component);
    parts.push_back(stage.render());
  }
  const std::vector<bool> mask = passtest::interiorMask(total, kMagenta);
  long count = 0;
  for (int y = 0; y < 160; ++y)
  {
    for (int x = 0; x < 160; ++x)
    {
      if (!mask[static_cast<size_t>(y) * 160 + x])
      {
        continue;
      }
      ++count;
      for (int c = 0; c < 3; ++c)
      {
        float sum = 0.0f;
        for (const Image& part : parts)
        {
          sum += part.at(x, y)[c];
        }
        ASSERT_NEAR(sum, total.at(x, y)[c], 2.5f / 255.0f) << x << "," << y;
      }
      // Emission alone is k_e everywhere.
      EXPECT_NEAR(parts[3].at(x, y)[2], scene.material.emission.z, 0.6f / 255.0f);
    }
  }
  EXPECT_GT(count, 5000);
}

TEST(ComponentViews, CosThetaOfADirectionalLight)
{
  // Grey N.L for a light shining along the view direction: at the pixel over
  // the sphere's centre N.L = 1; toward the rim it falls as the sphere's
  // analytic normal predicts.
  vtkSmartPointer<vtkPolyData> mesh = sphere(128);
  shadelab::Scene scene = sphereScene(shadelab::ShadingModel::Lambert);
  scene.camera.position = glm::vec3(0.0f, 0.0f, 5.0f);
  scene.lights.resize(1);
  scene.lights[0].direction = glm::vec3(0.0f, 0.0f, -1.0f);
  scene.frequency = shadelab::ShadingFrequency::Phong;
  passtest::Stage stage = passtest::litStage(mesh, scene, 200, 200);
  stage.pass->SetComponent(slLightingPass::COS_THETA);
  stage.pass->SetComponentLight(0);
  const Image image = stage.render();
  EXPECT_NEAR(image.at(100, 100)[0], 1.0f, 1.5f / 255.0f);
  // A point on the sphere at polar angle t from the view axis: N.L = cos t.
  for (double t : { 0.3, 0.6, 0.9 })
  {
    const double p[3] = { std::sin(t), 0.0, std::cos(t) };
    double d[2];
    stage.toDisplay(p, d);
    EXPECT_NEAR(image.at(static_cast<int>(d[0]), static_cast<int>(d[1]))[0], std::cos(t), 0.02) << t;
  }
}

TEST(ComponentViews, FalseColourIsTheFieldImagesRamp)
{
  // A plane facing the camera under one directional light at 50 degrees:
  // N.L and the diffuse term are the same at every pixel. The pass's false
  // colours must be slDiverging / slRamp as compiled in C++, which the field
  // images (slFieldImageRenderer) sample into their lookup tables.
  shadelab::Scene scene = sphereScene(shadelab::ShadingModel::Lambert);
  scene.frequency = shadelab::ShadingFrequency::Phong;
  scene.camera.position = glm::vec3(0.0f, 0.0f, 3.0f);
  scene.lights.resize(1);
  const float a = glm::radians(50.0f);
  scene.lights[0].direction = glm::vec3(std::sin(a), 0.0f, -std::cos(a));
  passtest::Stage stage = passtest::litStage(facingSquare(1.0), scene, 100, 100);
  stage.pass->FalseColorOn();
  stage.pass->SetComponentLight(0);

  stage.pass->SetComponent(slLightingPass::COS_THETA);
  const glm::vec3 cosColour = shadelab::glsl::slDiverging(std::cos(a));
  const Image rendered = stage.render(); // kept: at() points into it
  const float* p = rendered.at(50, 50);
  EXPECT_NEAR(p[0], cosColour.x, 1.0f / 255.0f);
  EXPECT_NEAR(p[1], cosColour.y, 1.0f / 255.0f);
  EXPECT_NEAR(p[2], cosColour.z, 1.0f / 255.0f);

  stage.pass->SetComponent(slLightingPass::DIFFUSE);
  const glm::vec3 diffuse = scene.lights[0].diffuse * scene.material.diffuse * std::cos(a);
  const glm::vec3 rampColour = shadelab::glsl::slRamp(shadelab::glsl::slLuminance(diffuse));
  const Image second = stage.render();
  const float* q = second.at(50, 50);
  EXPECT_NEAR(q[0], rampColour.x, 1.0f / 255.0f);
  EXPECT_NEAR(q[1], rampColour.y, 1.0f / 255.0f);
  EXPECT_NEAR(q[2], rampColour.z, 1.0f / 255.0f);
}

TEST(Parameters, ChangesUpdateTheImageAndVariantsComeBack)
{
  vtkSmartPointer<vtkPolyData> mesh = sphere(48);
  shadelab::Scene scene = sphereScene(shadelab::ShadingModel::Phong);
  scene.frequency = shadelab::ShadingFrequency::Phong;
  passtest::Stage stage = passtest::litStage(mesh, scene, 120, 120);
  const Image first = stage.render();
  const vtkMTimeType stageTime = stage.pass->GetShaderStageMTime();

  // A material change is a uniform change: new picture, same shader.
  shadelab::Scene shinier = scene;
  shinier.material.shininess = 80.0f;
  stage.pass->GetScene()->SetScene(shinier);
  const Image shiny = stage.render();
  EXPECT_EQ(stage.pass->GetShaderStageMTime(), stageTime) << "shininess is a uniform";
  EXPECT_NE(first.rgb, shiny.rgb);
  stage.pass->GetScene()->SetScene(scene);

  // Model and frequency are compiled in: each change is a shader variant.
  stage.pass->SetModel(shadelab::glsl::SL_MODEL_BLINN_PHONG);
  EXPECT_GT(stage.pass->GetShaderStageMTime(), stageTime);
  const Image blinn = stage.render();
  EXPECT_NE(first.rgb, blinn.rgb);
  stage.pass->SetFrequency(slLightingPass::GOURAUD);
  const Image gouraud = stage.render();
  EXPECT_NE(gouraud.rgb, blinn.rgb);

  // Back to the first variant (from VTK's shader cache): the same picture.
  stage.pass->SetFrequency(slLightingPass::PHONG);
  stage.pass->SetModel(shadelab::glsl::SL_MODEL_PHONG);
  EXPECT_EQ(stage.render().rgb, first.rgb);

  // Whether a component view is shown is compiled in (the total carries no
  // code for one); which component, a uniform.
  const vtkMTimeType totalTime = stage.pass->GetShaderStageMTime();
  stage.pass->SetComponent(slLightingPass::DIFFUSE);
  const vtkMTimeType viewTime = stage.pass->GetShaderStageMTime();
  EXPECT_GT(viewTime, totalTime) << "a component view is a shader variant";
  const Image diffuse = stage.render();
  EXPECT_NE(diffuse.rgb, first.rgb);
  stage.pass->SetComponent(slLightingPass::SPECULAR);
  EXPECT_EQ(stage.pass->GetShaderStageMTime(), viewTime) << "which component is a uniform";
  EXPECT_NE(stage.render().rgb, diffuse.rgb);
  stage.pass->SetComponent(slLightingPass::TOTAL);
  EXPECT_GT(stage.pass->GetShaderStageMTime(), viewTime);
  EXPECT_EQ(stage.render().rgb, first.rgb);
}

namespace
{
/// The same 8-bit RGB colour at every point, as the active scalars "Colours".
void setUniformColours(vtkPolyData* mesh, unsigned char r, unsigned char g, unsigned char b)
{
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("Colours");
  colours->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    colours->InsertNextTuple3(r, g, b);
  }
  mesh->GetPointData()->SetScalars(colours);
}

/// Lambert, k_d = 0.8, no ambient or emission, one white directional light
/// along the view from a camera at (0, 0, z): where N faces the camera the
/// pixel is 0.8 x base colour.
shadelab::Scene headOnLambert(float z)
{
  shadelab::Scene scene = sphereScene(shadelab::ShadingModel::Lambert);
  scene.camera.position = glm::vec3(0.0f, 0.0f, z);
  scene.lights.resize(1);
  scene.lights[0].direction = glm::vec3(0.0f, 0.0f, -1.0f);
  scene.lights[0].diffuse = glm::vec3(1.0f);
  scene.material.diffuse = glm::vec3(0.8f);
  scene.material.ambient = glm::vec3(0.0f);
  scene.material.emission = glm::vec3(0.0f);
  scene.frequency = shadelab::ShadingFrequency::Phong;
  return scene;
}
} // namespace

TEST(BaseColour, PointScalarsMultiplyKd)
{
  vtkSmartPointer<vtkPolyData> mesh = sphere(64);
  const shadelab::Scene scene = headOnLambert(5.0f);

  setUniformColours(mesh, 255, 128, 64); // base colour everywhere
  passtest::Stage stage = passtest::litStage(mesh, scene, 100, 100);
  stage.actor->GetMapper()->ScalarVisibilityOn();
  const Image rendered = stage.render(); // kept: at() points into it
  const float* pixel = rendered.at(50, 50);
  EXPECT_NEAR(pixel[0], 0.8f * 255.0f / 255.0f, 1.5f / 255.0f);
  EXPECT_NEAR(pixel[1], 0.8f * 128.0f / 255.0f, 1.5f / 255.0f);
  EXPECT_NEAR(pixel[2], 0.8f * 64.0f / 255.0f, 1.5f / 255.0f);
}

TEST(BaseColour, CPUAndGPUAgreeOnEightBitColours)
{
  // One colour rule for both paths: for an 8-bit colour array the CPU
  // filter's Radiance equals the pass's pixel (both take v / 255, no
  // transfer function, and both multiply k_a and k_d by it).
  vtkSmartPointer<vtkPolyData> mesh = sphere(64);
  const shadelab::Scene scene = headOnLambert(5.0f);
  setUniformColours(mesh, 200, 90, 30);
  vtkNew<slScene> sceneObject;
  sceneObject->SetScene(scene);
  vtkNew<slRadianceFilter> cpu;
  cpu->SetScene(sceneObject);
  cpu->SetDiffuseColorArrayName("Colours");
  cpu->SetInputData(mesh);
  cpu->Update();
  double front[3] = { 0.0, 0.0, 1.0 }; // the point facing the camera and the light
  const vtkIdType id = cpu->GetOutput()->FindPoint(front);
  double radiance[3];
  cpu->GetOutput()->GetPointData()->GetArray("Radiance")->GetTuple(id, radiance);

  passtest::Stage stage = passtest::litStage(mesh, scene, 100, 100);
  stage.actor->GetMapper()->ScalarVisibilityOn();
  const Image rendered = stage.render(); // kept: at() points into it
  const float* pixel = rendered.at(50, 50);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(pixel[c], radiance[c], 1.5 / 255.0) << c;
  }
  EXPECT_NEAR(radiance[1], 0.8 * 90.0 / 255.0, 1e-3); // k_d 0.8 times v / 255, lit head-on
}

TEST(BaseColour, ActorTextureMultipliesKd)
{
  const shadelab::Scene scene = headOnLambert(4.0f);

  vtkNew<vtkImageData> image; // a constant (200, 100, 50) texture
  image->SetDimensions(4, 4, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* texels = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int i = 0; i < 16; ++i)
  {
    texels[3 * i] = 200;
    texels[3 * i + 1] = 100;
    texels[3 * i + 2] = 50;
  }
  vtkNew<vtkTexture> texture;
  texture->SetInputData(image);
  passtest::Stage stage = passtest::litStage(facingSquare(1.0), scene, 100, 100); // texture coordinates over [0, 1]^2
  stage.actor->SetTexture(texture);
  const Image rendered = stage.render(); // kept: at() points into it
  const float* pixel = rendered.at(50, 50);
  EXPECT_NEAR(pixel[0], 0.8f * 200.0f / 255.0f, 1.5f / 255.0f);
  EXPECT_NEAR(pixel[1], 0.8f * 100.0f / 255.0f, 1.5f / 255.0f);
  EXPECT_NEAR(pixel[2], 0.8f * 50.0f / 255.0f, 1.5f / 255.0f);
}

TEST(UnlitActors, LightingOffKeepsVTKsUnlitColour)
{
  // A property with lighting off (widget handles, colour-mapped fields) must
  // not be lit by the pass: VTK draws it as ambient + diffuse colour, flat.
  vtkSmartPointer<vtkPolyData> mesh = sphere(32);
  passtest::Stage stage = passtest::litStage(mesh, headOnLambert(5.0f), 100, 100);
  vtkProperty* property = stage.actor->GetProperty();
  property->LightingOff();
  property->SetAmbient(0.0);
  property->SetDiffuse(1.0);
  property->SetColor(0.2, 0.4, 0.6);
  const Image image = stage.render();
  for (const int x : { 50, 40, 62 }) // centre and off-centre: lit shading would vary, unlit does not
  {
    const float* pixel = image.at(x, 50);
    EXPECT_NEAR(pixel[0], 0.2f, 1.5f / 255.0f) << x;
    EXPECT_NEAR(pixel[1], 0.4f, 1.5f / 255.0f) << x;
    EXPECT_NEAR(pixel[2], 0.6f, 1.5f / 255.0f) << x;
  }
}
