// sceneValueProblem(): the check of scenes not read from a file (built in
// code, or from VTK's lights and property), against the same limits as the
// scene file reader.
#include "shadelab/DefaultScene.h"
#include "shadelab/SceneLimits.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace shadelab;

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
  s.lights[0].position.z = INFINITY;
  EXPECT_EQ(sceneValueProblem(s), "lights[0] (\"key\").position[2]: inf is not a finite number");
  s = defaultScene();
  s.lights[0].attenuation.x = -1.0f;
  EXPECT_EQ(sceneValueProblem(s), "lights[0] (\"key\").attenuation[0]: -1 is out of range [0, inf]");
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
