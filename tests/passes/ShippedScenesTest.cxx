// Every shipped scene, as it is (fitted camera, camera-space lights), lights a
// mesh the same on the CPU (slRadianceFilter) as through the render pass, at
// portrait, landscape and square image sizes: both place the camera with the
// one rule of slScene::ApplyCamera.
#include "PassTestUtilities.h"

#include "shadelab/Scene.h"
#include "slRadianceFilter.h"
#include "slScene.h"
#include "VTKErrors.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkSphereSource.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace
{
const glm::vec3 kMagenta(1.0f, 0.0f, 1.0f);

/// An off-centre ellipsoid, so that the fit depends on its bounds.
vtkSmartPointer<vtkPolyData> ellipsoid()
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(64);
  source->SetPhiResolution(48);
  vtkNew<vtkTransform> transform;
  transform->Translate(0.7, -0.4, 0.3);
  transform->Scale(1.6, 1.0, 0.8);
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputConnection(source->GetOutputPort());
  moved->SetTransform(transform);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(moved->GetOutputPort());
  normals->SplittingOff();
  normals->Update();
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  return out;
}

std::vector<std::string> shippedScenes()
{
  std::vector<std::string> files;
  for (const char* folder : { "scenes", "scenes/regression" })
  {
    for (const auto& entry : std::filesystem::directory_iterator(std::string(SHADELAB_DATA_DIR) + "/" + folder))
    {
      if (entry.path().extension() == ".json")
      {
        files.push_back(entry.path().string());
      }
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

struct Case
{
  std::string file;
  int width, height;
};

/// How a case reads in test listings: the scene file and the image size.
void PrintTo(const Case& c, std::ostream* os)
{
  *os << std::filesystem::path(c.file).filename().string() << " at " << c.width << "x" << c.height;
}

std::vector<Case> cases()
{
  std::vector<Case> all;
  for (const std::string& file : shippedScenes())
  {
    for (const auto& size : { std::make_pair(120, 400), std::make_pair(400, 120), std::make_pair(256, 256) })
    {
      all.push_back({ file, size.first, size.second });
    }
  }
  return all;
}
} // namespace

class ShippedSceneAgrees : public ::testing::TestWithParam<Case>
{
};

TEST_P(ShippedSceneAgrees, CPUAndGPUWithin2Of255)
{
  const Case& c = GetParam();
  vtkNew<slScene> file;
  ASSERT_EQ(callError(file, [&] { return file->ReadFile(c.file.c_str()); }), "");
  shadelab::Scene scene = file->GetScene();
  ASSERT_FALSE(scene.camera.hasPosition) << c.file << ": the shipped scenes fit their camera";
  scene.width = c.width;
  scene.height = c.height;
  scene.frequency = shadelab::ShadingFrequency::Gouraud; // per vertex on both sides
  scene.material.diffuseTexture.clear();                 // the mesh has no texture coordinates
  scene.background = kMagenta;

  vtkSmartPointer<vtkPolyData> mesh = ellipsoid();
  // Where a vertex saturates, the pass interpolates the unclamped value and
  // the CPU colours the clamped one, a difference that has nothing to do
  // with the camera: scale every intensity and the emission (the radiance is
  // linear in them) so that no point exceeds 0.95. Geometry, camera and light
  // placement stay as the file gives them.
  {
    vtkNew<slScene> probeScene;
    probeScene->SetScene(scene);
    vtkNew<slRadianceFilter> probe;
    probe->SetScene(probeScene);
    probe->SetInputData(mesh);
    ASSERT_EQ(updateError(probe), "");
    vtkDataArray* radiance = probe->GetOutput()->GetPointData()->GetArray("Radiance");
    ASSERT_NE(radiance, nullptr);
    double brightest = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      brightest = std::max(brightest, radiance->GetRange(c)[1]);
    }
    if (brightest > 0.95)
    {
      const float k = static_cast<float>(0.95 / brightest);
      for (shadelab::SceneLight& light : scene.lights)
      {
        light.intensity *= k;
      }
      scene.material.emission *= k;
    }
  }
  const passtest::Image lit = passtest::litStage(mesh, scene, c.width, c.height).render();
  vtkNew<vtkPolyData> coloured;
  coloured->DeepCopy(mesh);
  passtest::colourPointsOnCPU(coloured, scene);
  const passtest::Image reference = passtest::unlitStage(coloured, scene, c.width, c.height, false).render();

  const passtest::Agreement a = passtest::agreement(lit, reference, passtest::interiorMask(reference, kMagenta));
  ASSERT_GT(a.covered, 2000) << c.file << ": the mesh should cover much of the image";
  EXPECT_GE(static_cast<double>(a.agreeing) / a.covered, 0.995)
    << c.file << " at " << c.width << "x" << c.height << ": worst difference " << a.worst * 255.0f << "/255";
}

INSTANTIATE_TEST_SUITE_P(EveryShippedScene, ShippedSceneAgrees, ::testing::ValuesIn(cases()),
  [](const ::testing::TestParamInfo<Case>& info) {
    std::string name = std::filesystem::path(info.param.file).parent_path().filename().string() + "_" +
      std::filesystem::path(info.param.file).stem().string() + "_" + std::to_string(info.param.width) + "x" +
      std::to_string(info.param.height);
    std::replace_if(name.begin(), name.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)); }, '_');
    return name;
  });
