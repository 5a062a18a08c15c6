// sceneValueProblem(): the check of scenes not read from a file (built in
// code, or from VTK's lights and property), against the same limits as the
// scene file reader.
#include "shadelab/DefaultScene.h"
#include "shadelab/SceneLimits.h"

#include <gtest/gtest.h>

#include <cmath>

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
  Scene s = defaultScene();
  ASSERT_GE(s.lights.size(), 2u);
  s.lights[1].intensity = NAN;
  EXPECT_EQ(sceneValueProblem(s), "lights[1] (\"fill\").intensity: nan is not a finite number");
  s = defaultScene();
  s.lights[0].diffuse.y = 2e6f;
  EXPECT_EQ(sceneValueProblem(s), "lights[0] (\"key\").diffuse[1]: 2e+06 is out of range [0, 1e+06]");
  s = defaultScene();
  s.lights[0].type = LightType::Point;
  s.lights[0].position.z = INFINITY;
  EXPECT_EQ(sceneValueProblem(s), "lights[0] (\"key\").position[2]: inf is not a finite number");
  s = defaultScene();
  s.lights[0].type = LightType::Point;
  s.lights[0].attenuation.x = -1.0f;
  EXPECT_EQ(sceneValueProblem(s), "lights[0] (\"key\").attenuation[0]: -1 is out of range [0, inf)");
  s = defaultScene();
  s.lights[0].intensity = INFINITY;
  EXPECT_EQ(sceneValueProblem(s), "lights[0] (\"key\").intensity: inf is not a finite number");
  s = defaultScene();
  s.lights[0].type = LightType::Directional;
  s.lights[0].cutoffDegrees = 0.0f; // a spot value: not used by a directional light
  EXPECT_EQ(sceneValueProblem(s), "");
  s.lights[0].type = LightType::Spot;
  EXPECT_EQ(sceneValueProblem(s), "lights[0] (\"key\").cutoff: 0 is out of range (0, 90]");
  s = defaultScene();
  s.lights[0].type = LightType::Spot;
  s.lights[0].cutoffDegrees = 20.0f;
  s.lights[0].edgeDegrees = 25.0f;
  EXPECT_EQ(sceneValueProblem(s), "lights[0] (\"key\").edge: 25 is out of range [0, 20]");
  s = defaultScene();
  s.material.shininess = NAN;
  EXPECT_EQ(sceneValueProblem(s), "material.shininess: nan is not a finite number");
  s = defaultScene();
  s.material.emission.x = -0.5f;
  EXPECT_EQ(sceneValueProblem(s), "material.emission[0]: -0.5 is out of range [0, 1e+06]");
  s = defaultScene();
  s.camera.focalPoint.x = NAN;
  EXPECT_EQ(sceneValueProblem(s), "camera.focalPoint[0]: nan is not a finite number");
}
