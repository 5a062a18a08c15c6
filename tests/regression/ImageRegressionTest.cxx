// Offscreen image regression tests: fixed scenes rendered at a fixed size
// under Xvfb, compared with data/baselines/<case>.png (metric in
// ImageComparison.h). Regenerate every baseline with
//   SHADELAB_UPDATE_BASELINES=1 bash scripts/test.sh -L regression
#include "ImageComparison.h"

#include "shadelab/LightingTables.h"
#include "shadelab/Scene.h"
#include "slBRDFLobeSource.h"
#include "slComparisonRenderer.h"
#include "slCosineField.h"
#include "slFieldImageRenderer.h"
#include "slPolyDataNormals.h"
#include "slPolyDataTangents.h"
#include "slLightingPass.h"
#include "slLobeImageRenderer.h"
#include "slMeshReader.h"
#include "slScene.h"
#include "slSceneRenderer.h"
#include "VTKErrors.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <sys/stat.h>

namespace
{
struct Case
{
  std::string name;
  std::string mesh;  ///< path
  std::string scene; ///< path
  std::string model;
  std::string frequency;
  int component = slLightingPass::TOTAL;
  bool falseColor = false;
  /// Give the mesh normals and tangents (slPolyDataTangents) first: the
  /// anisotropic models read them.
  bool tangents = false;
};

/// How a case reads in test listings: the mesh, the scene, the model, the
/// frequency and the component view, by name.
void PrintTo(const Case& c, std::ostream* os)
{
  const auto base = [](const std::string& path) { return path.substr(path.find_last_of('/') + 1); };
  *os << base(c.mesh) << (c.tangents ? " with tangents" : "") << " under " << base(c.scene) << ", " << c.model << ", "
      << c.frequency;
  if (c.component != slLightingPass::TOTAL)
  {
    *os << ", component " << c.component << (c.falseColor ? " in false colour" : "");
  }
}

std::string projectData(const std::string& relative)
{
  return std::string(SHADELAB_DATA_DIR) + "/" + relative;
}

std::string sharedMesh(const std::string& name)
{
  return std::string(SHADELAB_DATA_DIR) + "/meshes/" + name;
}

std::vector<Case> allCases()
{
  std::vector<Case> cases;
  // Every model (every row of LightingTables.h) x frequency with every
  // light type at once, on Spot; with its tangents for the anisotropic
  // models. The material's numbers are the scene format's defaults.
  for (const shadelab::LightingModelInfo& info : shadelab::kLightingModels)
  {
    const bool tangents = shadelab::modelNeedsTangents(info.model);
    for (const char* frequency : { "flat", "gouraud", "phong" })
    {
      cases.push_back({ std::string("spot-") + info.name + "-" + frequency, projectData("meshes/spot.obj"),
        projectData("scenes/regression/all-lights.json"), info.name, frequency, slLightingPass::TOTAL, false,
        tangents });
    }
  }
  // Each light type alone, on the shared reference meshes.
  cases.push_back({ "bunny-directional-blinn-phong-phong", sharedMesh("stanford-bunny.obj"),
    projectData("scenes/regression/directional.json"), "blinn-phong", "phong" });
  cases.push_back({ "bunny-point-phong-gouraud", sharedMesh("stanford-bunny.obj"),
    projectData("scenes/regression/point.json"), "phong", "gouraud" });
  cases.push_back({ "fandisk-spot-blinn-phong-flat", sharedMesh("fandisk.obj"),
    projectData("scenes/regression/spot.json"), "blinn-phong", "flat" });
  cases.push_back({ "fandisk-ambient-lambert-phong", sharedMesh("fandisk.obj"),
    projectData("scenes/regression/ambient.json"), "lambert", "phong" });
  // Component views.
  cases.push_back({ "spot-specular-grey", projectData("meshes/spot.obj"),
    projectData("scenes/regression/all-lights.json"), "blinn-phong", "phong", slLightingPass::SPECULAR, false });
  cases.push_back({ "spot-cos-false-colour", projectData("meshes/spot.obj"),
    projectData("scenes/regression/all-lights.json"), "lambert", "gouraud", slLightingPass::COS_THETA, true });
  // The specular term alone of every microfacet model (a distribution of
  // half vectors rather than a power of a cosine), per pixel, on a shiny
  // dielectric (F0 = 0.51) where it shows.
  for (const shadelab::LightingModelInfo& info : shadelab::kLightingModels)
  {
    const shadelab::SpecularLobe lobe = info.lobe;
    if (lobe != shadelab::SpecularLobe::None && lobe != shadelab::SpecularLobe::Mirror &&
      lobe != shadelab::SpecularLobe::Halfway)
    {
      cases.push_back({ std::string("spot-specular-") + info.name, projectData("meshes/spot.obj"),
        projectData("scenes/regression/microfacet.json"), info.name, "phong", slLightingPass::SPECULAR, false,
        shadelab::modelNeedsTangents(info.model) });
    }
  }
  return cases;
}

/// Compares with data/baselines/NAME.png, or rewrites that baseline when
/// SHADELAB_UPDATE_BASELINES=1.
void checkAgainstBaseline(vtkImageData* image, const std::string& name)
{
  const std::string baseline = projectData("baselines/" + name + ".png");
  const char* update = std::getenv("SHADELAB_UPDATE_BASELINES");
  if (update && std::string(update) == "1")
  {
    EXPECT_EQ(regression::writeBaseline(image, baseline), "");
    return;
  }
  const std::string failures = std::string(SHADELAB_TEST_OUTPUT_DIR);
  mkdir(failures.c_str(), 0755);
  const regression::Verdict verdict = regression::compareWithBaseline(image, baseline, failures, name);
  EXPECT_TRUE(verdict.passed) << verdict.message;
}

class ImageRegression : public ::testing::TestWithParam<Case>
{
};
} // namespace

TEST_P(ImageRegression, MatchesBaseline)
{
  const Case& c = GetParam();
  vtkNew<slMeshReader> reader;
  reader->SetFileName(c.mesh.c_str());
  ASSERT_EQ(updateError(reader), "");
  vtkSmartPointer<vtkPolyData> mesh = reader->GetOutput();
  if (c.tangents)
  {
    // As `shadelab tangents` makes them: normals first, then the frames.
    vtkNew<slPolyDataNormals> normals;
    normals->SetInputData(mesh);
    vtkNew<slPolyDataTangents> tangents;
    tangents->SetInputConnection(normals->GetOutputPort());
    ASSERT_EQ(updateError(tangents), "");
    mesh = tangents->GetOutput();
  }
  vtkNew<slScene> scene;
  ASSERT_EQ(callError(scene, [&] { return scene->ReadFile(c.scene.c_str()); }), "");
  ASSERT_TRUE(scene->SetModelName(c.model.c_str()));
  ASSERT_TRUE(scene->SetFrequencyName(c.frequency.c_str()));

  vtkNew<slSceneRenderer> renderer;
  renderer->SetScene(scene);
  renderer->SetMesh(mesh);
  renderer->GetLightingPass()->SetComponent(c.component);
  renderer->GetLightingPass()->SetFalseColor(c.falseColor);
  ASSERT_EQ(callError(renderer, [&] { return renderer->Render(); }), "");

  checkAgainstBaseline(renderer->GetImage(), c.name);
}

TEST(ImageRegressionCompare, FrequenciesSideBySideWithDifference)
{
  vtkNew<slMeshReader> reader;
  reader->SetFileName(projectData("meshes/spot.obj").c_str());
  reader->Update();
  vtkNew<slScene> scene;
  ASSERT_TRUE(scene->ReadFile(projectData("scenes/regression/all-lights.json").c_str()));
  vtkNew<slComparisonRenderer> comparison;
  comparison->SetScene(scene);
  comparison->SetMesh(reader->GetOutput());
  comparison->SetPanelWidth(160);
  comparison->SetPanelHeight(120);
  comparison->AddPanel("flat", "blinn-phong", "flat");
  comparison->AddPanel("Gouraud", "blinn-phong", "gouraud");
  comparison->AddPanel("Phong", "blinn-phong", "phong");
  comparison->SetDifference(1, 2, 8.0);
  ASSERT_EQ(callError(comparison, [&] { return comparison->Render(); }), "");
  checkAgainstBaseline(comparison->GetImage(), "compare-frequencies-diff");
}

TEST(ImageRegressionFields, CosineFieldsWithScalarBarsAndLightGlyphs)
{
  vtkNew<slMeshReader> reader;
  reader->SetFileName(projectData("meshes/spot.obj").c_str());
  vtkNew<slPolyDataNormals> normals;
  normals->SetInputConnection(reader->GetOutputPort());
  normals->SplittingOff();
  vtkNew<slScene> scene;
  ASSERT_TRUE(scene->ReadFile(projectData("scenes/regression/all-lights.json").c_str()));
  vtkNew<slCosineField> cosine;
  cosine->SetScene(scene);
  cosine->SetInputConnection(normals->GetOutputPort());
  ASSERT_EQ(updateError(cosine), "");
  vtkNew<slFieldImageRenderer> fields;
  fields->SetMesh(cosine->GetOutput());
  fields->SetScene(scene);
  fields->AddField("CosThetaRaw_0");
  fields->AddField("CosTheta_2");
  fields->SetPanelWidth(200);
  fields->SetPanelHeight(150);
  ASSERT_EQ(callError(fields, [&] { return fields->Render(); }), "");
  checkAgainstBaseline(fields->GetImage(), "fields-cosine-spot");
}

TEST(ImageRegressionLobes, ThreePartsWithModelsOverlaid)
{
  vtkNew<slLobeImageRenderer> lobes;
  ASSERT_TRUE(lobes->AddModel("phong"));
  ASSERT_TRUE(lobes->AddModel("blinn-phong-normalized"));
  lobes->GetLobeParameters()->SetIncidenceAngle(40.0);
  lobes->SetPanelWidth(240);
  lobes->SetPanelHeight(200);
  ASSERT_EQ(callError(lobes, [&] { return lobes->Render(); }), "");
  checkAgainstBaseline(lobes->GetImage(), "lobes-phong-blinn-normalized");
}

INSTANTIATE_TEST_SUITE_P(Scenes, ImageRegression, ::testing::ValuesIn(allCases()),
  [](const ::testing::TestParamInfo<Case>& info) {
    std::string name = info.param.name;
    for (char& ch : name)
    {
      ch = ch == '-' ? '_' : ch;
    }
    return name;
  });

namespace
{
/// A @p width x @p height RGB image whose channel c of pixel i is the level
/// level(i, c).
template <typename Level>
vtkSmartPointer<vtkImageData> levelImage(int width, int height, Level level)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* pixels = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int i = 0; i < width * height; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      pixels[3 * i + c] = static_cast<unsigned char>(level(i, c));
    }
  }
  return image;
}
} // namespace

TEST(ImageRegressionMetric, CountsWholeLevels)
{
  // Every level 0..255 against a baseline 2 levels off passes: "more than
  // 2/255" is 3 levels. Compared as floats (a multiply on one side, a
  // division on the other), about half of such pixels failed.
  const std::string folder = SHADELAB_TEST_OUTPUT_DIR;
  mkdir(folder.c_str(), 0755);
  const std::string baseline = folder + "/metric-baseline.png";
  const auto base = [](int i, int c) { return (i + 85 * c) % 254; };
  ASSERT_EQ(regression::writeBaseline(levelImage(254, 4, base), baseline), "");
  const auto plusTwo = [&](int i, int c) { return base(i, c) + 2; };
  const regression::Verdict two = regression::compareWithBaseline(levelImage(254, 4, plusTwo), baseline, folder, "metric");
  EXPECT_TRUE(two.passed) << two.message;
  EXPECT_EQ(two.failingPixels, 0) << two.message;
  EXPECT_DOUBLE_EQ(two.maxError * 255.0, 2.0);

  // Three levels off in one channel of 3 pixels: those 3 fail, which 0.2 %
  // of 1016 pixels (2) does not allow.
  const auto threeOff = [&](int i, int c) { return base(i, c) + (i < 3 && c == 1 ? 3 : 0); };
  const regression::Verdict three = regression::compareWithBaseline(levelImage(254, 4, threeOff), baseline, folder, "metric");
  EXPECT_FALSE(three.passed) << three.message;
  EXPECT_EQ(three.failingPixels, 3) << three.message;
  EXPECT_DOUBLE_EQ(three.maxError * 255.0, 3.0);
}
