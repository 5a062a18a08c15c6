// slLightingPass with a BRDF Explorer .brdf file: the shipped energy-
// normalised Blinn-Phong file draws the built-in model's image at every
// frequency; the BRDF frame (X, Y) comes from the mesh's Tangents or from
// the normal; a GLSL error is one line with the file's line; a parameter is
// a uniform.
#include "PassTestUtilities.h"

#include "shadelab/Scene.h"
#include "shadelab/SceneKeys.h"
#include "slLightingPass.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkSphereSource.h>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <string>

using passtest::Image;

namespace
{
const glm::vec3 kMagenta(1.0f, 0.0f, 1.0f);
const std::string kBlinnPhongFile = std::string(SHADELAB_DATA_DIR) + "/brdf/blinn-phong-normalized.brdf";

vtkSmartPointer<vtkPolyData> sphere()
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(40);
  source->SetPhiResolution(40);
  source->SetRadius(1.0);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(source->GetOutputPort());
  normals->SplittingOff();
  normals->Update();
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  return out;
}

/// blinn-phong-normalized with grey k_d = k_s = 0.5 and n = 50 (the .brdf
/// file's defaults), every light type, each light's diffuse colour equal
/// to its specular one (the .brdf BRDF takes one light colour).
shadelab::Scene blinnPhongScene(shadelab::ShadingFrequency frequency)
{
  shadelab::Scene s;
  s.model = shadelab::ShadingModel::BlinnPhongNormalized;
  s.frequency = frequency;
  s.background = kMagenta;
  s.camera.hasPosition = true;
  s.camera.position = glm::vec3(0.3f, 0.5f, 4.0f);
  s.camera.focalPoint = glm::vec3(0.0f);
  s.material.ambient = glm::vec3(0.2f, 0.25f, 0.3f);
  s.material.diffuse = glm::vec3(0.5f);
  s.material.specular = glm::vec3(0.5f);
  s.material.emission = glm::vec3(0.02f, 0.0f, 0.03f);
  s.material.shininess = 50.0f;

  // One light of each type (directional, point, spot in camera space with a
  // smooth edge, ambient), each with one colour for diffuse and specular.
  const glm::vec3 colours[] = { { 0.9f, 0.85f, 0.8f }, { 0.6f, 0.4f, 0.2f }, { 0.2f, 0.4f, 0.6f } };
  for (int t = 0; t < 4; ++t)
  {
    shadelab::SceneLight l = shadelab::defaultLight(static_cast<shadelab::LightType>(t));
    if (l.type == shadelab::LightType::Ambient)
    {
      l.ambient = glm::vec3(0.15f);
      s.lights.push_back(l);
      continue;
    }
    l.diffuse = l.specular = colours[t];
    l.ambient = glm::vec3(0.05f);
    l.intensity = t == 0 ? 1.5f : 1.0f;
    l.position = t == 1 ? glm::vec3(2.0f, 1.0f, 1.5f) : glm::vec3(0.0f, 1.0f, 1.0f);
    l.direction = t == 0 ? glm::vec3(-0.4f, -0.5f, -1.0f) : glm::vec3(0.0f, -1.0f, -1.0f);
    l.attenuation = glm::vec3(0.5f, 0.0f, 0.1f);
    l.space = t == 2 ? shadelab::LightSpace::Camera : shadelab::LightSpace::World;
    l.cutoffDegrees = 40.0f;
    l.edgeDegrees = 10.0f;
    l.exponent = 2.0f;
    s.lights.push_back(l);
  }
  return s;
}

/// Every pixel, silhouettes included: both images draw the same triangles.
std::vector<bool> everyPixel(const Image& image)
{
  return std::vector<bool>(static_cast<size_t>(image.width) * image.height, true);
}

/// The largest channel difference between two images, in 1/255.
float worstDifference(const Image& a, const Image& b)
{
  return passtest::agreement(a, b, everyPixel(a)).worst * 255.0f;
}

const char* const kFrequencies[] = { "flat", "gouraud", "phong" };
} // namespace

class BrdfFileInThePass : public ::testing::TestWithParam<int>
{
};

TEST_P(BrdfFileInThePass, BlinnPhongFileDrawsTheBuiltInModel)
{
  const shadelab::Scene scene = blinnPhongScene(static_cast<shadelab::ShadingFrequency>(GetParam()));
  vtkSmartPointer<vtkPolyData> mesh = sphere();

  passtest::Stage builtIn = passtest::litStage(mesh, scene, 240, 240);
  const Image expected = builtIn.render();

  passtest::Stage fromFile = passtest::litStage(mesh, scene, 240, 240);
  ASSERT_TRUE(fromFile.pass->LoadBrdfFile(kBlinnPhongFile.c_str()));
  const Image actual = fromFile.render();
  EXPECT_STREQ(fromFile.pass->GetBrdfError(), "");

  // The images are not trivially equal: the sphere is lit and highlighted.
  const passtest::Agreement covered = passtest::agreement(expected, actual, passtest::interiorMask(expected, kMagenta));
  ASSERT_GT(covered.covered, 15000) << "the sphere should cover much of the window";
  float brightest = 0.0f;
  for (int y = 0; y < expected.height; ++y)
  {
    for (int x = 0; x < expected.width; ++x)
    {
      brightest = std::max(brightest, expected.luminance(x, y) * (expected.at(x, y)[1] > 0.0f ? 1.0f : 0.0f));
    }
  }
  EXPECT_GT(brightest, 0.6f) << "a highlight should show";

  EXPECT_LE(worstDifference(expected, actual), 2.0f) << kFrequencies[GetParam()];
}

TEST_P(BrdfFileInThePass, ParameterIsAUniformThatChangesTheImage)
{
  // k_s = 0 in the file is the built-in model with k_s = 0: the image
  // changes as the model's does, and no shader is built again.
  shadelab::Scene scene = blinnPhongScene(static_cast<shadelab::ShadingFrequency>(GetParam()));
  vtkSmartPointer<vtkPolyData> mesh = sphere();
  passtest::Stage fromFile = passtest::litStage(mesh, scene, 200, 200);
  ASSERT_TRUE(fromFile.pass->LoadBrdfFile(kBlinnPhongFile.c_str()));
  const Image before = fromFile.render();
  const int builds = fromFile.pass->GetNumberOfShaderBuilds();
  ASSERT_GT(builds, 0);

  ASSERT_TRUE(fromFile.pass->SetBrdfParameter("ks", 0.0));
  const Image after = fromFile.render();
  EXPECT_EQ(fromFile.pass->GetNumberOfShaderBuilds(), builds) << "a parameter change rebuilt a shader";
  EXPECT_GT(worstDifference(before, after), 20.0f) << "removing the highlight should change the image";

  scene.material.specular = glm::vec3(0.0f);
  passtest::Stage builtIn = passtest::litStage(mesh, scene, 200, 200);
  EXPECT_LE(worstDifference(builtIn.render(), after), 2.0f);

  // A bad value leaves the parameters as they were.
  EXPECT_FALSE(fromFile.pass->SetBrdfParameter("ks", 2.0));
  EXPECT_FALSE(fromFile.pass->SetBrdfParameter("nosuch=1"));
  double value[3];
  fromFile.pass->GetBrdfParameterValue(1, value);
  EXPECT_EQ(value[0], 0.0);
}

INSTANTIATE_TEST_SUITE_P(EveryFrequency, BrdfFileInThePass, ::testing::Range(0, 3),
  [](const ::testing::TestParamInfo<int>& info) { return std::string(kFrequencies[info.param]); });

namespace
{
/// The square [-1, 1]^2 on z = 0 facing +z (toward the camera), with point
/// normals and, when @p handedness is not 0, 4-component Tangents along +x.
vtkSmartPointer<vtkPolyData> square(float handedness)
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-1, -1, 0);
  points->InsertNextPoint(1, -1, 0);
  points->InsertNextPoint(1, 1, 0);
  points->InsertNextPoint(-1, 1, 0);
  vtkNew<vtkCellArray> polys;
  const vtkIdType quad[4] = { 0, 1, 2, 3 };
  polys->InsertNextCell(4, quad);
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> tangents;
  tangents->SetName("Tangents");
  tangents->SetNumberOfComponents(4);
  for (int i = 0; i < 4; ++i)
  {
    normals->InsertNextTuple3(0, 0, 1);
    const float t[4] = { 1, 0, 0, handedness };
    tangents->InsertNextTypedTuple(t);
  }
  mesh->GetPointData()->SetNormals(normals);
  if (handedness != 0.0f)
  {
    mesh->GetPointData()->AddArray(tangents);
  }
  return mesh;
}

/// A BRDF that shows its frame: red 0.5 + 0.4 X.x, green 0.5 + 0.4 Y.y,
/// blue 0.5 + 0.4 (X x Y).N.
const char* const kFrameBrdf = "::begin parameters\n"
                               "::end parameters\n"
                               "::begin shader\n"
                               "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)\n"
                               "{\n"
                               "  return vec3(0.5) + 0.4 * vec3(X.x, Y.y, dot(cross(X, Y), N));\n"
                               "}\n"
                               "::end shader\n";

/// The centre pixel of the square under a light along the view axis
/// (N.L = 1, white, no ambient): the BRDF's value.
glm::vec3 centreOfSquare(float handedness, shadelab::ShadingFrequency frequency)
{
  shadelab::Scene scene;
  scene.frequency = frequency;
  scene.background = glm::vec3(0.0f);
  scene.camera.hasPosition = true;
  scene.camera.position = glm::vec3(0.0f, 0.0f, 4.0f);
  scene.material.ambient = scene.material.emission = glm::vec3(0.0f);
  shadelab::SceneLight light;
  light.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  scene.lights = { light };
  passtest::Stage stage = passtest::litStage(square(handedness), scene, 64, 64);
  EXPECT_TRUE(stage.pass->SetBrdfText(kFrameBrdf, "frame.brdf"));
  const Image image = stage.render();
  const float* c = image.at(32, 32);
  return glm::vec3(c[0], c[1], c[2]);
}
} // namespace

TEST(BrdfFrame, TangentsWithHandednessOrAFrameFromTheNormal)
{
  for (int f = 0; f < 3; ++f)
  {
    SCOPED_TRACE(kFrequencies[f]);
    const auto frequency = static_cast<shadelab::ShadingFrequency>(f);
    // Tangent +x, w = -1: X = +x, Y = w (N x X) = -y, X x Y = -N.
    const glm::vec3 left = centreOfSquare(-1.0f, frequency);
    EXPECT_NEAR(left.r, 0.9f, 2.0f / 255.0f);
    EXPECT_NEAR(left.g, 0.1f, 2.0f / 255.0f);
    EXPECT_NEAR(left.b, 0.1f, 2.0f / 255.0f);
    // No Tangents: a right-handed frame around N = +z (X x Y = N); for
    // N = +z the frame built from the normal is +x, +y.
    const glm::vec3 none = centreOfSquare(0.0f, frequency);
    EXPECT_NEAR(none.r, 0.9f, 2.0f / 255.0f);
    EXPECT_NEAR(none.g, 0.9f, 2.0f / 255.0f);
    EXPECT_NEAR(none.b, 0.9f, 2.0f / 255.0f);
  }
}

TEST(BrdfCompileError, OneLineWithTheFilesLine)
{
  // Line 6 of the file calls a function that does not exist.
  const char* const broken = "::begin parameters\n"
                             "float k 0 1 0.5\n"
                             "::end parameters\n"
                             "::begin shader\n"
                             "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {\n"
                             "  return vec3(k) * noSuchFunction(L);\n"
                             "}\n"
                             "::end shader\n";
  const shadelab::Scene scene = blinnPhongScene(shadelab::ShadingFrequency::Phong);
  passtest::Stage stage = passtest::litStage(sphere(), scene, 64, 64);
  ASSERT_TRUE(stage.pass->SetBrdfText(broken, "broken.brdf"));
  stage.render();
  const std::string error = stage.pass->GetBrdfError();
  const std::string prefix = "broken.brdf:6: ";
  EXPECT_EQ(error.rfind(prefix, 0), 0u) << error;
  EXPECT_GT(error.size(), prefix.size()) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;

  // The same text again (VTK keeps the variant built for it): still the error.
  ASSERT_TRUE(stage.pass->SetBrdfText(broken, "broken.brdf"));
  EXPECT_EQ(stage.pass->GetBrdfError(), error);
  stage.render();
  EXPECT_EQ(stage.pass->GetBrdfError(), error);

  // A correct text afterwards compiles and clears the error.
  ASSERT_TRUE(stage.pass->LoadBrdfFile(kBlinnPhongFile.c_str()));
  stage.render();
  EXPECT_STREQ(stage.pass->GetBrdfError(), "");
}

TEST(BrdfComponentViews, TheReflectionIsTheDiffuseTerm)
{
  // The file's reflection shows in the diffuse view: for the Blinn-Phong
  // file, the model's diffuse plus specular views; its specular view is black.
  const shadelab::Scene scene = blinnPhongScene(shadelab::ShadingFrequency::Phong);
  vtkSmartPointer<vtkPolyData> mesh = sphere();
  auto view = [&](bool brdf, int component) {
    passtest::Stage stage = passtest::litStage(mesh, scene, 160, 160);
    if (brdf)
    {
      EXPECT_TRUE(stage.pass->LoadBrdfFile(kBlinnPhongFile.c_str()));
    }
    stage.pass->SetComponent(component);
    return stage.render();
  };
  const Image diffuse = view(false, slLightingPass::DIFFUSE);
  const Image specular = view(false, slLightingPass::SPECULAR);
  const Image reflection = view(true, slLightingPass::DIFFUSE);
  const Image none = view(true, slLightingPass::SPECULAR);
  float worst = 0.0f, brightest = 0.0f;
  long covered = 0, black = 0;
  for (int y = 0; y < diffuse.height; ++y)
  {
    for (int x = 0; x < diffuse.width; ++x)
    {
      const float* p = none.at(x, y);
      if (p[0] == kMagenta.r && p[1] == kMagenta.g && p[2] == kMagenta.b)
      {
        continue; // the background
      }
      ++covered;
      black += p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f ? 1 : 0;
      for (int c = 0; c < 3; ++c)
      {
        const float sum = std::min(1.0f, diffuse.at(x, y)[c] + specular.at(x, y)[c]);
        worst = std::max(worst, std::abs(sum - reflection.at(x, y)[c]));
        brightest = std::max(brightest, specular.at(x, y)[c]);
      }
    }
  }
  ASSERT_GT(covered, 5000);
  EXPECT_EQ(black, covered) << "the specular view of a .brdf BRDF is black";
  EXPECT_GT(brightest, 0.3f) << "the model's highlight should show in its specular view";
  EXPECT_LE(worst * 255.0f, 3.0f) << "two rounded images summed: up to 3/255";
}
