// slScene <-> vtkLight / vtkProperty / vtkCamera, both ways.
#include "slImageWriter.h"
#include "slScene.h"
#include "TestFolder.h"

#include "shadelab/Scene.h"
#include "VTKErrors.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace
{
const char* kScene = R"({
  "shading": {"model": "phong", "frequency": "gouraud"},
  "material": {"ambient": [0.2, 0.3, 0.4], "diffuse": [0.5, 0.6, 0.7], "specular": [0.9, 0.8, 0.7],
               "shininess": 40, "emission": [0.1, 0, 0]},
  "camera": {"position": [1, 2, 10], "focalPoint": [1, 2, 0], "viewUp": [0, 1, 0], "viewAngle": 25},
  "lights": [
    {"type": "directional", "direction": [0, 0, -2], "diffuse": [1, 0.5, 0.25], "intensity": 0.8},
    {"type": "point", "position": [3, 4, 5], "attenuation": [0.5, 0.1, 0.01], "ambient": [0.1, 0.1, 0.1]},
    {"type": "spot", "space": "camera", "position": [0, 0, 1], "direction": [0, 0, -1],
     "cutoff": 20, "exponent": 5, "edge": 4},
    {"type": "ambient", "ambient": [0.5, 0.5, 0.5], "intensity": 2}
  ]})";

vtkSmartPointer<slScene> loadScene()
{
  auto scene = vtkSmartPointer<slScene>::New();
  EXPECT_EQ(callError(scene, [&] { return scene->ReadString(kScene, "conversion.json"); }), "");
  return scene;
}

std::vector<vtkLight*> lightsOf(vtkRenderer* renderer)
{
  std::vector<vtkLight*> out;
  vtkLightCollection* lights = renderer->GetLights();
  lights->InitTraversal();
  while (vtkLight* l = lights->GetNextItem())
  {
    out.push_back(l);
  }
  return out;
}
} // namespace

TEST(SceneConversion, LightsToVTK)
{
  auto scene = loadScene();
  vtkNew<vtkRenderer> renderer;
  scene->ApplyLights(renderer);
  const std::vector<vtkLight*> lights = lightsOf(renderer);
  ASSERT_EQ(lights.size(), 3u) << "the ambient light goes into the property instead";

  // Directional: VTK's light comes from Position toward FocalPoint.
  EXPECT_FALSE(lights[0]->GetPositional());
  double* p = lights[0]->GetPosition();
  double* f = lights[0]->GetFocalPoint();
  EXPECT_NEAR(p[2] - f[2], 2.0, 1e-9);
  EXPECT_NEAR(lights[0]->GetIntensity(), 0.8, 1e-7);
  EXPECT_NEAR(lights[0]->GetDiffuseColor()[1], 0.5, 1e-7);
  EXPECT_TRUE(lights[0]->LightTypeIsSceneLight());

  EXPECT_TRUE(lights[1]->GetPositional());
  EXPECT_GE(lights[1]->GetConeAngle(), 90.0) << "a point light is no spot";
  double a[3];
  lights[1]->GetAttenuationValues(a);
  EXPECT_NEAR(a[0], 0.5, 1e-7);
  EXPECT_NEAR(a[2], 0.01, 1e-7);

  EXPECT_TRUE(lights[2]->LightTypeIsCameraLight());
  EXPECT_NEAR(lights[2]->GetConeAngle(), 20.0, 1e-6);
  EXPECT_NEAR(lights[2]->GetExponent(), 5.0, 1e-6);

  const std::string notes = scene->GetConversionNotes();
  EXPECT_NE(notes.find("lights[1].ambient: VTK's shaders ignore a light's ambient colour"), std::string::npos);
  EXPECT_NE(notes.find("lights[1].attenuation: VTK has no min(1, .) clamp"), std::string::npos);
  EXPECT_NE(notes.find("lights[2].edge: VTK's spot cone has a hard edge"), std::string::npos);
}

TEST(SceneConversion, MaterialToVTK)
{
  auto scene = loadScene();
  vtkNew<vtkProperty> property;
  scene->ApplyMaterial(property);
  // Ambient colour = k_a times the ambient lights (0.5 * 2 = 1).
  EXPECT_NEAR(property->GetAmbient() * property->GetAmbientColor()[1], 0.3, 1e-6);
  EXPECT_NEAR(property->GetDiffuse() * property->GetDiffuseColor()[2], 0.7, 1e-6);
  EXPECT_NEAR(property->GetSpecular() * property->GetSpecularColor()[0], 0.9, 1e-6);
  EXPECT_NEAR(property->GetSpecularPower(), 40.0, 1e-6);
  EXPECT_EQ(property->GetInterpolation(), VTK_GOURAUD);
  const std::string notes = scene->GetConversionNotes();
  EXPECT_NE(notes.find("material.emission"), std::string::npos);
  EXPECT_NE(notes.find("VTK 9.1 lights Gouraud per fragment"), std::string::npos);
}

TEST(SceneConversion, NotesOfLightsAndMaterialAddUpInEitherOrder)
{
  // A scene applied to an actor and to a renderer lists what both lose,
  // whichever comes first; applying one part again replaces only its notes.
  for (const bool actorFirst : { true, false })
  {
    auto scene = loadScene();
    vtkNew<vtkRenderer> renderer;
    vtkNew<vtkActor> actor;
    renderer->AddActor(actor);
    if (actorFirst)
    {
      EXPECT_TRUE(scene->ApplyToActor(actor));
      scene->ApplyToRenderer(renderer);
    }
    else
    {
      scene->ApplyToRenderer(renderer);
      EXPECT_TRUE(scene->ApplyToActor(actor));
    }
    std::string notes = scene->GetConversionNotes();
    EXPECT_NE(notes.find("material.emission"), std::string::npos) << actorFirst;
    EXPECT_NE(notes.find("lights[2].edge"), std::string::npos) << actorFirst;

    scene->ApplyToRenderer(renderer);
    EXPECT_EQ(std::string(scene->GetConversionNotes()), notes) << "applied twice, listed once";
    vtkNew<vtkProperty> plain;
    plain->SetInterpolationToPhong();
    scene->SetMaterialFromVTK(plain);
    notes = scene->GetConversionNotes();
    EXPECT_EQ(notes.find("material."), std::string::npos) << notes;
    EXPECT_NE(notes.find("lights[2].edge"), std::string::npos) << notes;
  }
}

TEST(SceneConversion, PrintSelfShowsTheWholeSceneAndItsNotes)
{
  auto scene = loadScene();
  std::ostringstream before;
  scene->Print(before);
  EXPECT_NE(before.str().find("ConversionNotes: (none)"), std::string::npos) << before.str();
  vtkNew<vtkProperty> property;
  scene->ApplyMaterial(property);
  std::ostringstream after;
  scene->Print(after);
  const std::string text = after.str();
  // Numbers only the JSON part holds: the shininess, a spot's cutoff, the camera.
  for (const char* item : { "\"shininess\": 40.0", "\"cutoff\": 20.0", "\"viewAngle\": 25.0", "material.emission" })
  {
    EXPECT_NE(text.find(item), std::string::npos) << item << "\n" << text;
  }
}

TEST(SceneConversion, LambertTurnsVTKSpecularOff)
{
  auto scene = loadScene();
  ASSERT_TRUE(scene->SetModelName("lambert"));
  vtkNew<vtkProperty> property;
  scene->ApplyMaterial(property);
  EXPECT_EQ(property->GetSpecular(), 0.0);
}

TEST(SceneConversion, CameraToVTK)
{
  auto scene = loadScene();
  vtkNew<vtkRenderer> renderer;
  scene->ApplyCamera(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  EXPECT_NEAR(camera->GetPosition()[2], 10.0, 1e-9);
  EXPECT_NEAR(camera->GetFocalPoint()[0], 1.0, 1e-9);
  EXPECT_NEAR(camera->GetViewAngle(), 25.0, 1e-9);
}

TEST(SceneConversion, VTKLightsBackToScene)
{
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkLight> spot;
  spot->SetPositional(true);
  spot->SetPosition(1, 2, 3);
  spot->SetFocalPoint(1, 2, 0);
  spot->SetConeAngle(15);
  spot->SetExponent(3);
  spot->SetAttenuationValues(1, 0.2, 0.03);
  spot->SetDiffuseColor(0.9, 0.8, 0.7);
  renderer->AddLight(spot);
  vtkNew<vtkLight> head;
  head->SetLightTypeToHeadlight();
  renderer->AddLight(head);
  vtkNew<vtkLight> off;
  off->SwitchOff();
  renderer->AddLight(off);

  vtkNew<slScene> scene;
  scene->SetLightsFromVTK(renderer->GetLights());
  const shadelab::Scene& s = scene->GetScene();
  ASSERT_EQ(s.lights.size(), 3u) << "implicit ambient + spot + headlight; the switched-off light is skipped";
  EXPECT_EQ(s.lights[0].type, shadelab::LightType::Ambient);
  const shadelab::SceneLight& l = s.lights[1];
  EXPECT_EQ(l.type, shadelab::LightType::Spot);
  EXPECT_FLOAT_EQ(l.cutoffDegrees, 15.0f);
  EXPECT_FLOAT_EQ(l.exponent, 3.0f);
  EXPECT_FLOAT_EQ(l.attenuation.z, 0.03f);
  EXPECT_FLOAT_EQ(l.diffuse.y, 0.8f);
  EXPECT_NEAR(glm::dot(glm::normalize(l.direction), glm::vec3(0, 0, -1)), 1.0, 1e-6);
  EXPECT_EQ(s.lights[2].type, shadelab::LightType::Directional);
  EXPECT_EQ(s.lights[2].space, shadelab::LightSpace::Camera);
  EXPECT_NE(std::string(scene->GetConversionNotes()).find("switched off"), std::string::npos);
}

TEST(SceneConversion, AVTKSceneLightsTransformMatrixPlacesIt)
{
  // A positional scene light at (0, 0, 2) shining at the origin, turned 90
  // degrees about x by its TransformMatrix: VTK lights from (0, -2, 0)
  // towards the origin, and so must the scene.
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(true);
  light->SetConeAngle(90.0);
  light->SetPosition(0, 0, 2);
  light->SetFocalPoint(0, 0, 0);
  vtkNew<vtkMatrix4x4> turn; // (x, y, z) -> (x, -z, y)
  turn->SetElement(1, 1, 0);
  turn->SetElement(1, 2, -1);
  turn->SetElement(2, 1, 1);
  turn->SetElement(2, 2, 0);
  light->SetTransformMatrix(turn);
  vtkNew<vtkLightCollection> lights;
  lights->AddItem(light);
  vtkNew<slScene> scene;
  scene->SetLightsFromVTK(lights);
  const shadelab::Scene& s = scene->GetScene();
  ASSERT_EQ(s.lights.size(), 2u) << "VTK's implicit ambient light and the point light";
  const shadelab::SceneLight& l = s.lights[1];
  EXPECT_EQ(l.type, shadelab::LightType::Point);
  EXPECT_EQ(l.space, shadelab::LightSpace::World);
  EXPECT_NEAR(l.position.x, 0.0f, 1e-6);
  EXPECT_NEAR(l.position.y, -2.0f, 1e-6);
  EXPECT_NEAR(l.position.z, 0.0f, 1e-6);
  EXPECT_NEAR(glm::dot(glm::normalize(l.direction), glm::vec3(0, 1, 0)), 1.0, 1e-6);
}

TEST(SceneConversion, RoundTripThroughVTKKeepsWhatVTKCanHold)
{
  auto scene = loadScene();
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkActor> actor;
  renderer->AddActor(actor);
  scene->ApplyToRenderer(renderer);
  scene->ApplyMaterial(actor->GetProperty());

  vtkNew<slScene> back;
  back->SetLightsFromVTK(renderer->GetLights());
  back->SetMaterialFromVTK(actor->GetProperty());
  back->SetCameraFromVTK(renderer->GetActiveCamera());
  const shadelab::Scene& a = scene->GetScene();
  const shadelab::Scene& b = back->GetScene();
  ASSERT_EQ(b.lights.size(), 4u);
  for (size_t i = 0; i < 3; ++i)
  {
    EXPECT_EQ(b.lights[i + 1].type, a.lights[i].type) << i;
    EXPECT_EQ(b.lights[i + 1].space, a.lights[i].space) << i;
    EXPECT_FLOAT_EQ(b.lights[i + 1].intensity, a.lights[i].intensity) << i;
    EXPECT_NEAR(glm::dot(glm::normalize(b.lights[i + 1].direction), glm::normalize(a.lights[i].direction)), 1.0, 1e-6);
  }
  // k_a came back multiplied by the ambient lights' total (1) under VTK's implicit white ambient light.
  EXPECT_NEAR(b.material.ambient.y, a.material.ambient.y, 1e-6);
  EXPECT_NEAR(b.material.shininess, a.material.shininess, 1e-6);
  EXPECT_EQ(b.frequency, a.frequency);
  EXPECT_NEAR(b.camera.viewAngle, a.camera.viewAngle, 1e-6);
  EXPECT_EQ(b.camera.position, a.camera.position);
}

TEST(SceneConversion, CameraLightsMatchVTKTransform)
{
  // A camera-space point light, moved to world space by the core, must land
  // where VTK puts the same vtkLight after its camera-light transform.
  auto scene = vtkSmartPointer<slScene>::New();
  ASSERT_TRUE(scene->ReadString(R"({
    "camera": {"position": [2, 3, 9], "focalPoint": [1, -1, 2], "viewUp": [0, 1, 0]},
    "lights": [{"type": "point", "space": "camera", "position": [0.3, -0.4, 0.5]}]})"));
  vtkNew<vtkRenderer> renderer;
  scene->ApplyToRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkLight* light = lightsOf(renderer).at(0);
  light->SetTransformMatrix(camera->GetCameraLightTransformMatrix());
  double world[3];
  light->GetTransformedPosition(world);

  const shadelab::Scene& s = scene->GetScene();
  const shadelab::SceneLight moved =
    shadelab::lightInWorldSpace(s.lights[0], s.camera.position, s.camera.focalPoint, glm::vec3(camera->GetViewUp()[0],
      camera->GetViewUp()[1], camera->GetViewUp()[2]));
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_NEAR(moved.position[i], world[i], 1e-4) << i;
  }

  // And back: VTK's world position, taken into camera space, is the scene's
  // camera-space position again (what the viewer's light widgets rely on).
  shadelab::SceneLight placed = s.lights[0];
  placed.space = shadelab::LightSpace::World;
  placed.position = glm::vec3(world[0], world[1], world[2]);
  placed.direction = moved.direction;
  const shadelab::SceneLight back = shadelab::lightInCameraSpace(placed, s.camera.position, s.camera.focalPoint,
    glm::vec3(camera->GetViewUp()[0], camera->GetViewUp()[1], camera->GetViewUp()[2]));
  EXPECT_EQ(back.space, shadelab::LightSpace::Camera);
  const float expected[3] = { 0.3f, -0.4f, 0.5f };
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_NEAR(back.position[i], expected[i], 1e-5) << i;
    EXPECT_NEAR(back.direction[i], s.lights[0].direction[i], 1e-5) << i;
  }
}

TEST(SceneConversion, UnreadableTextureNamesTheImageAndTheScene)
{
  vtkNew<slScene> scene;
  ASSERT_EQ(callError(scene, [&] {
    return scene->ReadString(R"({"material": {"diffuseTexture": "/nonexistent/albedo.png"}})", "textured.json");
  }),
    "");
  vtkNew<vtkActor> actor;
  const std::string error = callError(scene, [&] { return scene->ApplyToActor(actor); });
  EXPECT_EQ(error.rfind("/nonexistent/albedo.png: cannot read image", 0), 0u) << error;
  const std::string suffix = " (material.diffuseTexture of textured.json)";
  ASSERT_GE(error.size(), suffix.size()) << error;
  EXPECT_EQ(error.substr(error.size() - suffix.size()), suffix) << error;
}

TEST(SceneConversion, DeepTexturesReachVTKAsStoredValues)
{
  // 8-bit textures stay unsigned char (v / 255); deeper ones (read as
  // float) reach the vtkTexture as float in direct-scalars mode, not through
  // its lookup table: values above 1 kept, the CPU's rule for the rest (not
  // finite: 0; clamped to +-1e6). The rendering tests: SceneTextureTest.
  const TestFolder folder;
  const float inf = std::numeric_limits<float>::infinity();
  const float values[6] = { 0.25f, 2.5f, std::numeric_limits<float>::quiet_NaN(), inf, -1e7f, 1e7f };
  const double expected[6] = { 0.25, 2.5, 0.0, 0.0, -1e6, 1e6 };
  vtkNew<vtkImageData> image;
  image->SetDimensions(2, 1, 1);
  image->AllocateScalars(VTK_FLOAT, 3);
  std::copy(values, values + 6, static_cast<float*>(image->GetScalarPointer()));
  vtkNew<vtkImageData> bytes;
  bytes->SetDimensions(2, 1, 1);
  bytes->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (int i = 0; i < 6; ++i)
  {
    static_cast<unsigned char*>(bytes->GetScalarPointer())[i] = static_cast<unsigned char>(40 * i);
  }
  for (vtkImageData* picture : { image.Get(), bytes.Get() })
  {
    const bool deep = picture == image.Get();
    const std::string file = folder.path(deep ? "deep.exr" : "bytes.png");
    vtkNew<slImageWriter> writer;
    writer->SetInputData(picture);
    writer->SetFileName(file.c_str());
    ASSERT_EQ(callError(writer, [&] { return writer->Write(); }), "") << file;

    vtkNew<slScene> scene;
    ASSERT_EQ(callError(scene, [&] {
      const std::string json = "{\"material\": {\"diffuseTexture\": \"" + file + "\"}}";
      return scene->ReadString(json.c_str(), "textured.json");
    }),
      "");
    vtkNew<vtkActor> actor;
    ASSERT_EQ(callError(scene, [&] { return scene->ApplyToActor(actor); }), "") << file;
    vtkTexture* texture = actor->GetTexture();
    ASSERT_NE(texture, nullptr) << file;
    EXPECT_EQ(texture->GetColorMode(), VTK_COLOR_MODE_DIRECT_SCALARS) << file;
    texture->Update();
    vtkImageData* input = texture->GetInput();
    ASSERT_NE(input, nullptr) << file;
    vtkDataArray* scalars = input->GetPointData()->GetScalars();
    ASSERT_NE(scalars, nullptr) << file;
    EXPECT_EQ(scalars->GetDataType(), deep ? VTK_FLOAT : VTK_UNSIGNED_CHAR) << file;
    ASSERT_EQ(scalars->GetNumberOfValues(), 6) << file;
    for (vtkIdType i = 0; i < 6; ++i)
    {
      EXPECT_EQ(scalars->GetComponent(i / 3, static_cast<int>(i % 3)), deep ? expected[i] : 40.0 * i) << file << " " << i;
    }
  }
}
