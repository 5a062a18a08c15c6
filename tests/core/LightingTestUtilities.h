#ifndef shadelab_tests_LightingTestUtilities_h
#define shadelab_tests_LightingTestUtilities_h
// Small builders for test lights and materials. Expected values in the tests
// are computed with <cmath> from first principles, never through the code
// under test.

#include "shadelab/LightingGLSL.h"
#include "shadelab/LightingTables.h"
#include "shadelab/Scene.h"

#include <cmath>
#include <vector>

namespace shadelab
{
namespace test
{
using glsl::slLight;
using glsl::slMaterial;

constexpr double kPi = 3.14159265358979323846;

inline double radians(double degrees)
{
  return degrees * kPi / 180.0;
}

/// Every row of the model table, as the int the formulas take.
inline std::vector<int> allModels()
{
  std::vector<int> models;
  for (const LightingModelInfo& m : kLightingModels)
  {
    models.push_back(static_cast<int>(m.model));
  }
  return models;
}

/// A white light of the given type with unit colours and no ambient part.
inline slLight whiteLight(int type)
{
  slLight l;
  l.type = type;
  l.position = glm::vec3(0.0f);
  l.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  l.ambient = glm::vec3(0.0f);
  l.diffuse = glm::vec3(1.0f);
  l.specular = glm::vec3(1.0f);
  l.intensity = 1.0f;
  l.attenuation = glm::vec3(1.0f, 0.0f, 0.0f);
  l.cosCutoff = -1.0f;
  l.cosInner = -1.0f;
  l.exponent = 0.0f;
  return l;
}

/// A directional light arriving from the unit direction @p toLight.
inline slLight directionalFrom(const glm::vec3& toLight)
{
  slLight l = whiteLight(glsl::SL_LIGHT_DIRECTIONAL);
  l.direction = -toLight;
  return l;
}

/// Grey k_d and k_s, no ambient, no emission; the other parameters
/// (roughness, index of refraction) the scene format's defaults.
inline slMaterial greyMaterial(float kd, float ks, float shininess)
{
  slMaterial m = toEvaluationMaterial(SceneMaterial());
  m.ambient = glm::vec3(0.0f);
  m.diffuse = glm::vec3(kd);
  m.specular = glm::vec3(ks);
  m.emission = glm::vec3(0.0f);
  m.shininess = shininess;
  return m;
}

/// k_d = k_s = 1, no ambient, no emission.
inline slMaterial unitMaterial(float shininess)
{
  return greyMaterial(1.0f, 1.0f, shininess);
}

/// The unit vector at polar angle theta from +z, azimuth phi (radians).
inline glm::vec3 polar(double theta, double phi = 0.0)
{
  return glm::vec3(static_cast<float>(std::sin(theta) * std::cos(phi)),
    static_cast<float>(std::sin(theta) * std::sin(phi)), static_cast<float>(std::cos(theta)));
}

} // namespace test
} // namespace shadelab

#endif
