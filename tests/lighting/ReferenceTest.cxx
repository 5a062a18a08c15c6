// slRadianceReference: the Monte Carlo radiance equation against analytic
// values (white furnace, uniform sky), the discrete Lambert formula for a
// small distant light, zero variance where theory says so, and 1/sqrt(N).
#include "LightingTestMeshes.h"

#include "TestFolder.h"
#include "slImageWriter.h"
#include "slRadianceReference.h"
#include "VTKErrors.h"

#include <vtkCallbackCommand.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <iostream>

using namespace shadelab;
using namespace shadelab::test;

namespace
{
/// A constant equirectangular environment of radiance @p rgb (16 x 8 texels).
vtkSmartPointer<vtkImageData> constantSky(const glm::vec3& rgb, int width = 16, int height = 8)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  vtkNew<vtkFloatArray> pixels;
  pixels->SetNumberOfComponents(3);
  for (int i = 0; i < width * height; ++i)
  {
    pixels->InsertNextTuple3(rgb.x, rgb.y, rgb.z);
  }
  image->GetPointData()->SetScalars(pixels);
  return image;
}

/// A scene with material k_d and no ambient, specular or emission.
vtkSmartPointer<slScene> lambertScene(const std::vector<SceneLight>& lights, const glm::vec3& kd)
{
  vtkSmartPointer<slScene> scene = makeScene(lights, ShadingModel::LambertNormalized);
  Scene s = scene->GetScene();
  s.material.ambient = s.material.specular = s.material.emission = glm::vec3(0.0f);
  s.material.diffuse = kd;
  scene->SetScene(s);
  return scene;
}

vtkSmartPointer<vtkPolyData> reference(slRadianceReference* filter, vtkPolyData* mesh)
{
  filter->SetInputData(mesh);
  EXPECT_EQ(updateError(filter), "");
  return filter->GetOutput();
}

/// Checks that every point's estimate is within 5 sigma of @p expected, and
/// the mean over points within 3 sigma of the mean (+ @p slack).
void expectWithinSigma(vtkPolyData* out, const glm::vec3& expected, double slack = 1e-5)
{
  const vtkIdType n = out->GetNumberOfPoints();
  for (int c = 0; c < 3; ++c)
  {
    double sum = 0.0, variance = 0.0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double x = tuple3(out, "Radiance", i)[c], sigma = tuple3(out, "RadianceStdError", i)[c];
      EXPECT_LE(std::abs(x - expected[c]), 5.0 * sigma + slack) << "point " << i << " channel " << c;
      sum += x;
      variance += sigma * sigma;
    }
    EXPECT_LE(std::abs(sum / n - expected[c]), 3.0 * std::sqrt(variance) / n + slack) << "channel " << c;
  }
}
} // namespace

TEST(RadianceReference, WhiteFurnaceGivesOneForEveryStrategy)
{
  for (int strategy = 0; strategy <= 4; ++strategy)
  {
    vtkNew<slRadianceReference> filter;
    filter->SetScene(lambertScene({}, glm::vec3(1.0f)));
    filter->UseSceneLightsOff();
    filter->SetEnvironmentMap(constantSky(glm::vec3(1.0f)));
    filter->SetStrategy(strategy);
    filter->SetSamplesPerPoint(64);
    vtkPolyData* out = reference(filter, sphere(8));
    SCOPED_TRACE("strategy " + std::to_string(strategy));
    expectWithinSigma(out, glm::vec3(1.0f));
  }
}

TEST(RadianceReference, UniformSkyOnLambertGivesAlbedoTimesSky)
{
  const glm::vec3 sky(0.7f, 0.5f, 2.0f), kd(0.8f, 0.6f, 0.25f);
  vtkNew<slRadianceReference> filter;
  filter->SetScene(lambertScene({}, kd));
  filter->SetEnvironmentMap(constantSky(sky));
  filter->SetStrategyToUniform();
  filter->SetSamplesPerPoint(128);
  expectWithinSigma(reference(filter, sphere(8)), kd * sky);
}

TEST(RadianceReference, CosineWeightedLambertUnderUniformSkyHasZeroVariance)
{
  const glm::vec3 sky(1.5f), kd(0.5f, 0.25f, 1.0f);
  vtkNew<slRadianceReference> filter;
  filter->SetScene(lambertScene({}, kd));
  filter->SetEnvironmentMap(constantSky(sky));
  filter->SetStrategyToCosine();
  filter->SetSamplesPerPoint(16);
  vtkPolyData* out = reference(filter, sphere(8));
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_LT(tuple3(out, "RadianceStdError", i)[c], 1e-6);
      EXPECT_NEAR(tuple3(out, "Radiance", i)[c], kd[c] * sky[c], 1e-5);
    }
  }
}

TEST(RadianceReference, SmallDistantLightAgreesWithDiscreteLambert)
{
  // A directional light of 0.25 degrees angular radius: the reference must
  // match (k_d / pi) I cos(theta), computed here, to well under a percent.
  SceneLight sun = whiteLight(LightType::Directional);
  sun.direction = -glm::normalize(glm::vec3(0.3f, 0.5f, 1.0f));
  sun.intensity = 3.0f;
  const glm::vec3 kd(0.9f, 0.5f, 0.2f);
  for (int strategy : { slRadianceReference::LIGHT, slRadianceReference::MIS })
  {
    vtkNew<slRadianceReference> filter;
    filter->SetScene(lambertScene({ sun }, kd));
    filter->SetDirectionalLightAngle(0.25);
    filter->SetStrategy(strategy);
    filter->SetSamplesPerPoint(32);
    vtkSmartPointer<vtkPolyData> mesh = sphere(10);
    vtkPolyData* out = reference(filter, mesh);
    const glm::vec3 L = -glm::normalize(sun.direction);
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      double n[3];
      mesh->GetPointData()->GetNormals()->GetTuple(i, n);
      const double cosTheta = (n[0] * L.x + n[1] * L.y + n[2] * L.z) / std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (cosTheta < 0.05)
      {
        continue; // the light's disc straddles the horizon
      }
      for (int c = 0; c < 3; ++c)
      {
        const double expected = kd[c] / kPi * 3.0 * cosTheta;
        EXPECT_NEAR(tuple3(out, "Radiance", i)[c], expected, 0.005 * expected + 3.0 * tuple3(out, "RadianceStdError", i)[c])
          << "strategy " << strategy << " point " << i;
        EXPECT_NEAR(tuple3(out, "DiscreteRadiance", i)[c], expected, 1e-5);
      }
    }
    vtkDataArray* rms = out->GetFieldData()->GetArray("RadianceErrorRMS");
    ASSERT_NE(rms, nullptr);
    EXPECT_LT(rms->GetComponent(0, 0), 0.01);
  }
}

TEST(RadianceReference, ErrorFollowsOneOverSqrtN)
{
  // MIS on a Blinn-Phong surface under the studio environment:
  // RMSE against a 16384-sample MIS reference falls by ~2 per 4x samples.
  const std::string envmap = std::string(SHADELAB_DATA_DIR) + "/envmaps/studio_small_03_1k.hdr";
  vtkSmartPointer<vtkPolyData> mesh = sphere(6);
  auto run = [&](int strategy, int samples, int seed) {
    vtkNew<slRadianceReference> filter;
    vtkSmartPointer<slScene> scene = makeScene({}, ShadingModel::BlinnPhongNormalized);
    filter->SetScene(scene);
    filter->SetEnvironmentFileName(envmap.c_str());
    filter->SetStrategy(strategy);
    filter->SetSamplesPerPoint(samples);
    filter->SetSeed(seed);
    vtkSmartPointer<vtkPolyData> out = reference(filter, mesh);
    return out;
  };
  vtkSmartPointer<vtkPolyData> truth = run(slRadianceReference::MIS, 16384, 99);
  std::vector<double> rmse;
  for (int samples : { 16, 64, 256 })
  {
    double sum = 0.0;
    int count = 0;
    for (int seed = 1; seed <= 4; ++seed)
    {
      vtkSmartPointer<vtkPolyData> out = run(slRadianceReference::MIS, samples, seed);
      for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
      {
        const double d = tuple3(out, "Radiance", i)[1] - tuple3(truth, "Radiance", i)[1];
        sum += d * d;
        ++count;
      }
    }
    rmse.push_back(std::sqrt(sum / count));
  }
  EXPECT_NEAR(rmse[0] / rmse[1], 2.0, 0.5);
  EXPECT_NEAR(rmse[1] / rmse[2], 2.0, 0.5);
  std::cout << "RMSE at 16, 64, 256 samples: " << rmse[0] << " " << rmse[1] << " " << rmse[2] << "\n";
}

TEST(RadianceReference, SameSeedSameResultAndProgressIsReported)
{
  int progressEvents = 0;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progressEvents);
  onProgress->SetCallback([](vtkObject*, unsigned long, void* data, void*) { ++*static_cast<int*>(data); });
  vtkSmartPointer<vtkPolyData> a, b;
  for (auto* out : { &a, &b })
  {
    vtkNew<slRadianceReference> filter;
    filter->SetScene(lambertScene({}, glm::vec3(0.5f)));
    filter->SetEnvironmentMap(constantSky(glm::vec3(1.0f, 2.0f, 3.0f)));
    filter->SetStrategyToUniform();
    filter->SetSamplesPerPoint(8);
    filter->AddObserver(vtkCommand::ProgressEvent, onProgress);
    *out = reference(filter, sphere(8));
  }
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    EXPECT_EQ(tuple3(a, "Radiance", i), tuple3(b, "Radiance", i));
  }
  EXPECT_GT(progressEvents, 10);
}

TEST(RadianceReference, BadEnvironmentMapsAndNoLight)
{
  TestFolder folder;
  folder.write("broken.hdr", "this is not an image");
  auto expectError = [](slRadianceReference* filter, const std::string& message) {
    filter->SetInputData(sphere(6));
    EXPECT_EQ(updateError(filter), message);
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  };
  {
    vtkNew<slRadianceReference> filter;
    filter->SetEnvironmentFileName("/nonexistent/sky.hdr");
    filter->SetInputData(sphere(6));
    const std::string error = updateError(filter);
    EXPECT_EQ(error.rfind("/nonexistent/sky.hdr: cannot read image", 0), 0u) << error;
  }
  {
    vtkNew<slRadianceReference> filter;
    filter->SetEnvironmentFileName(folder.path("broken.hdr").c_str());
    filter->SetInputData(sphere(6));
    const std::string error = updateError(filter);
    EXPECT_EQ(error.rfind(folder.path("broken.hdr") + ": cannot read image", 0), 0u) << error;
  }
  {
    vtkNew<slRadianceReference> filter;
    filter->SetEnvironmentMap(constantSky(glm::vec3(1.0f), 8, 8));
    expectError(filter, "EnvironmentMap: environment map is 8 x 8 pixels; an equirectangular environment map must be "
                        "twice as wide as it is high");
  }
  {
    vtkNew<slRadianceReference> filter;
    filter->SetScene(lambertScene({}, glm::vec3(1.0f)));
    expectError(filter, "no light for the reference: give an environment map or a scene with (non-ambient) lights");
  }
}

TEST(RadianceReference, DiffuseTextureColoursKdAtTheTextureCoordinates)
{
  // Lambert under a uniform sky, cosine-weighted: every sample gives
  // k_d * texel * L_sky exactly. Texture 2 x 1: red then blue; u = 0.25 and
  // 0.75 are the texels' centres, so the bilinear lookup gives each alone.
  const glm::vec3 red(0.8f, 0.2f, 0.1f), blue(0.1f, 0.3f, 0.9f), kd(0.5f), sky(1.5f);
  vtkNew<vtkImageData> texture;
  texture->SetDimensions(2, 1, 1);
  vtkNew<vtkFloatArray> texels;
  texels->SetNumberOfComponents(3);
  texels->InsertNextTuple3(red.x, red.y, red.z);
  texels->InsertNextTuple3(blue.x, blue.y, blue.z);
  texture->GetPointData()->SetScalars(texels);
  vtkSmartPointer<vtkPolyData> mesh = pointsWithNormals({ { 0, 0, 0, 0, 0, 1 }, { 1, 0, 0, 0, 0, 1 } });
  vtkNew<slRadianceReference> filter;
  filter->SetScene(lambertScene({}, kd));
  filter->SetEnvironmentMap(constantSky(sky));
  filter->SetStrategyToCosine();
  filter->SetSamplesPerPoint(8);
  filter->SetDiffuseTexture(texture);
  // Without texture coordinates: the error slRadianceFilter gives, no output.
  filter->SetInputData(mesh);
  EXPECT_EQ(updateError(filter), "input mesh: a diffuse texture needs point texture coordinates, and the mesh has none");
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);

  vtkNew<vtkFloatArray> uv;
  uv->SetNumberOfComponents(2);
  uv->InsertNextTuple2(0.25, 0.5);
  uv->InsertNextTuple2(0.75, 0.5);
  mesh->GetPointData()->SetTCoords(uv);
  mesh->Modified();
  vtkPolyData* out = reference(filter, mesh);
  for (vtkIdType i = 0; i < 2; ++i)
  {
    const glm::vec3 texel = i == 0 ? red : blue;
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(tuple3(out, "Radiance", i)[c], kd[c] * texel[c] * sky[c], 1e-5) << "point " << i;
    }
  }
}

TEST(RadianceReference, DiffuseColorArrayAndTextureFileColourKdInTheFiltersOrder)
{
  // Lambert under a uniform sky, cosine-weighted: every sample gives
  // k_d * base * L_sky exactly, whatever gives the base colour. Two points,
  // at the centres (u = 0.25, 0.75) of a 2 x 1 PNG's texels.
  const glm::vec3 kd(0.5f, 0.8f, 0.6f), sky(1.5f);
  const unsigned char texels[2][3] = { { 204, 51, 25 }, { 25, 76, 229 } };
  const glm::vec3 fromFile[2] = { glm::vec3(texels[0][0], texels[0][1], texels[0][2]) / 255.0f,
    glm::vec3(texels[1][0], texels[1][1], texels[1][2]) / 255.0f };
  const glm::vec3 fromArray[2] = { glm::vec3(0.9f, 0.4f, 0.2f), glm::vec3(0.3f, 0.6f, 1.0f) };
  const glm::vec3 green(0.1f, 0.7f, 0.2f); // the one texel of the image given with SetDiffuseTexture()

  TestFolder folder;
  const std::string png = folder.path("t.png");
  {
    vtkNew<vtkImageData> image;
    image->SetDimensions(2, 1, 1);
    vtkNew<vtkUnsignedCharArray> bytes;
    bytes->SetNumberOfComponents(3);
    bytes->InsertNextTypedTuple(texels[0]);
    bytes->InsertNextTypedTuple(texels[1]);
    image->GetPointData()->SetScalars(bytes);
    vtkNew<slImageWriter> writer;
    writer->SetInputData(image);
    writer->SetFileName(png.c_str());
    ASSERT_EQ(callError(writer, [&] { return writer->Write(); }), "");
  }
  vtkNew<vtkImageData> image;
  image->SetDimensions(1, 1, 1);
  vtkNew<vtkFloatArray> pixel;
  pixel->SetNumberOfComponents(3);
  pixel->InsertNextTuple3(green.x, green.y, green.z);
  image->GetPointData()->SetScalars(pixel);

  vtkSmartPointer<vtkPolyData> mesh = pointsWithNormals({ { 0, 0, 0, 0, 0, 1 }, { 1, 0, 0, 0, 0, 1 } });
  vtkNew<vtkFloatArray> uv;
  uv->SetNumberOfComponents(2);
  uv->InsertNextTuple2(0.25, 0.5);
  uv->InsertNextTuple2(0.75, 0.5);
  mesh->GetPointData()->SetTCoords(uv);
  vtkNew<vtkFloatArray> base;
  base->SetName("Base");
  base->SetNumberOfComponents(3);
  for (const glm::vec3& b : fromArray)
  {
    base->InsertNextTuple3(b.x, b.y, b.z);
  }
  mesh->GetPointData()->AddArray(base);

  vtkNew<slRadianceReference> filter;
  filter->SetScene(lambertScene({}, kd));
  filter->SetEnvironmentMap(constantSky(sky));
  filter->SetStrategyToCosine();
  filter->SetSamplesPerPoint(8);
  auto expectBase = [&](const glm::vec3 (&expected)[2], const char* what) {
    vtkPolyData* out = reference(filter, mesh);
    ASSERT_EQ(out->GetNumberOfPoints(), 2) << what;
    for (vtkIdType i = 0; i < 2; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(tuple3(out, "Radiance", i)[c], kd[c] * expected[i][c] * sky[c], 1e-5)
          << what << ", point " << i << ", channel " << c;
      }
    }
  };
  const glm::vec3 fromImage[2] = { green, green };

  // slRadianceFilter's order: the array, then the file, then the image.
  filter->SetDiffuseColorArrayName("Base");
  filter->SetDiffuseTextureFileName(png.c_str());
  filter->SetDiffuseTexture(image);
  expectBase(fromArray, "array, file and image");
  filter->SetDiffuseColorArrayName("");
  expectBase(fromFile, "file and image");
  filter->SetDiffuseTextureFileName(nullptr);
  expectBase(fromImage, "image");

  // slRadianceFilter's errors, and no output.
  auto expectError = [&](const std::string& message) {
    filter->SetInputData(mesh);
    const std::string error = updateError(filter);
    EXPECT_EQ(error.substr(0, message.size()), message) << error;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  };
  filter->SetDiffuseColorArrayName("Nope");
  expectError("input mesh: no point array \"Nope\" for the diffuse colour");
  filter->SetDiffuseColorArrayName(nullptr);
  filter->SetDiffuseTextureFileName("/nonexistent/t.png");
  expectError("/nonexistent/t.png: cannot read image");
}

TEST(RadianceReference, DegenerateMeshGivesNoNaN)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  vtkSmartPointer<vtkPolyData> mesh = pointsWithNormals(
    { { 0, 0, 0, 0, 0, 0 }, { 0, 0, 0, nan, 0, 1 }, { 1, 1, 1, 0, 0, 1 }, { 0, 0, 10, 0, 0, 1 } });
  SceneLight point = whiteLight(LightType::Point);
  point.position = glm::vec3(1.0f, 1.0f, 1.0f);
  for (int strategy = 0; strategy <= 4; ++strategy)
  {
    for (int model = 0; model < kLightingModelCount; ++model)
    {
      vtkNew<slRadianceReference> filter;
      filter->SetScene(makeScene({ point }, static_cast<ShadingModel>(model), glm::vec3(0.0f, 0.0f, 10.0f)));
      filter->SetEnvironmentMap(constantSky(glm::vec3(1.0f)));
      filter->ZeroNormalsAreErrorsOff();
      filter->SetStrategy(strategy);
      filter->SetSamplesPerPoint(8);
      vtkPolyData* out = reference(filter, mesh);
      EXPECT_TRUE(allFinite(out)) << strategy << " " << model;
    }
  }
}
