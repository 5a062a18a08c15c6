// sceneValueProblem(): the check of scenes not read from a file (built in
// code, or from VTK's lights and property), against the same limits as the
// scene file reader.
#include "shadelab/DefaultScene.h"
#include "shadelab/SceneLimits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

using namespace shadelab;

TEST(SceneLimits, NumberProblemWordsEveryCase)
{
  EXPECT_EQ(numberProblem(0.5, 0.0, 1.0), "");
  EXPECT_EQ(numberProblem(NAN, 0.0, 1.0), "nan is not a finite number");
  EXPECT_EQ(numberProblem(-3.5e38, -HUGE_VAL, HUGE_VAL), "-3.5e+38 is beyond the float range");
  EXPECT_EQ(numberProblem(2.0, 0.0, 1.0), "2 is out of range [0, 1]");
  EXPECT_EQ(numberProblem(0.0, 0.0, 1.0, true), "0 is out of range (0, 1]");
  EXPECT_EQ(numberProblem(1.0, 0.0, 1.0, false, true), "1 is out of range [0, 1)");
  EXPECT_EQ(numberProblem(-1.0, 0.0, HUGE_VAL), "-1 is out of range [0, inf)");
}

TEST(SceneLimits, TheDefaultSceneIsValid)
{
  EXPECT_EQ(sceneValueProblem(defaultScene()), "");
}

TEST(SceneLimits, NamesTheFirstValueThatIsNotFiniteOrOutOfRange)
{
  // One case per value the check covers: { what to break, the message }.
  // Light 0 of the default scene is "key"; it becomes a spot first, so that
  // every light value is one it uses.
  using Edit = std::function<void(Scene&)>;
  const std::vector<std::pair<Edit, std::string>> cases = {
    { [](Scene& s) { s.lights[0].ambient.x = NAN; }, "ambient[0]: nan is not a finite number" },
    { [](Scene& s) { s.lights[0].diffuse.y = 2e6f; }, "diffuse[1]: 2e+06 is out of range [0, 1e+06]" },
    { [](Scene& s) { s.lights[0].specular.z = -1.0f; }, "specular[2]: -1 is out of range [0, 1e+06]" },
    { [](Scene& s) { s.lights[0].intensity = INFINITY; }, "intensity: inf is not a finite number" },
    { [](Scene& s) { s.lights[0].position.z = INFINITY; }, "position[2]: inf is not a finite number" },
    { [](Scene& s) { s.lights[0].attenuation.x = -1.0f; }, "attenuation[0]: -1 is out of range [0, inf)" },
    { [](Scene& s) { s.lights[0].direction.y = NAN; }, "direction[1]: nan is not a finite number" },
    // The scene reader refuses a zero direction, so nothing may write one.
    { [](Scene& s) { s.lights[0].direction = glm::vec3(0.0f); }, "direction: a direction must not have zero length" },
    { [](Scene& s) { s.lights[0].cutoffDegrees = 0.0f; }, "cutoff: 0 is out of range (0, 90]" },
    { [](Scene& s) { s.lights[0].exponent = 2e4f; }, "exponent: 20000 is out of range [0, 10000]" },
    { [](Scene& s) { s.lights[0].edgeDegrees = 45.0f; }, "edge: 45 is out of range [0, 30]" },
  };
  for (const auto& c : cases)
  {
    Scene s = defaultScene();
    s.lights[0].type = LightType::Spot;
    s.lights[0].cutoffDegrees = 30.0f;
    ASSERT_EQ(sceneValueProblem(s), "");
    c.first(s);
    EXPECT_EQ(sceneValueProblem(s), "lights[0] (\"key\")." + c.second);
  }
  const std::vector<std::pair<Edit, std::string>> materialAndCamera = {
    { [](Scene& s) { s.material.ambient.x = NAN; }, "material.ambient[0]: nan is not a finite number" },
    { [](Scene& s) { s.material.diffuse.y = 3e6f; }, "material.diffuse[1]: 3e+06 is out of range [0, 1e+06]" },
    { [](Scene& s) { s.material.specular.z = 1e30f; }, "material.specular[2]: 1e+30 is out of range [0, 1e+06]" },
    { [](Scene& s) { s.material.emission.x = -0.5f; }, "material.emission[0]: -0.5 is out of range [0, 1e+06]" },
    { [](Scene& s) { s.material.shininess = NAN; }, "material.shininess: nan is not a finite number" },
    { [](Scene& s) { s.camera.position.y = -INFINITY; }, "camera.position[1]: -inf is not a finite number" },
    { [](Scene& s) { s.camera.focalPoint.x = NAN; }, "camera.focalPoint[0]: nan is not a finite number" },
    { [](Scene& s) { s.camera.viewUp = glm::vec3(0.0f); }, "camera.viewUp: a direction must not have zero length" },
  };
  for (const auto& c : materialAndCamera)
  {
    Scene s = defaultScene();
    c.first(s);
    EXPECT_EQ(sceneValueProblem(s), c.second);
  }
}

TEST(SceneLimits, TheFirstProblemAndOnlyTheValuesALightTypeUses)
{
  Scene s = defaultScene();
  ASSERT_GE(s.lights.size(), 2u);
  // Two problems: the first one in scene order is named.
  s.lights[1].intensity = NAN;
  s.material.shininess = -1.0f;
  EXPECT_EQ(sceneValueProblem(s), "lights[1] (\"fill\").intensity: nan is not a finite number");
  s.lights[0].diffuse.x = -2.0f;
  EXPECT_EQ(sceneValueProblem(s), "lights[0] (\"key\").diffuse[0]: -2 is out of range [0, 1e+06]");
  // A directional light has no position, attenuation or cone: whatever those
  // hold is never used, so it is no error (scene files do not accept them).
  s = defaultScene();
  s.lights[0].type = LightType::Directional;
  s.lights[0].position.x = NAN;
  s.lights[0].attenuation.y = -1.0f;
  s.lights[0].cutoffDegrees = 0.0f;
  EXPECT_EQ(sceneValueProblem(s), "");
  s.lights[0].type = LightType::Point;
  EXPECT_EQ(sceneValueProblem(s), "lights[0] (\"key\").position[0]: nan is not a finite number");
}

TEST(SceneLimits, AModelOrLightTypeOutsideTheTablesIsAProblem)
{
  // Built in code (a cast, a VTK setter's int): not silently shaded as
  // another model or type.
  Scene s = defaultScene();
  s.model = static_cast<ShadingModel>(kLightingModelCount);
  EXPECT_EQ(sceneValueProblem(s).rfind("shading.model: " + std::to_string(kLightingModelCount) +
                " is not a lighting model (0 lambert, 1 phong, 2 blinn-phong",
              0),
    0u)
    << sceneValueProblem(s);
  s = defaultScene();
  s.lights[1].type = static_cast<LightType>(-1);
  EXPECT_EQ(sceneValueProblem(s).rfind("lights[1] (\"fill\").type: -1 is not a light type (0 directional, 1 point", 0), 0u)
    << sceneValueProblem(s);
}
