#include "shadelab/SceneLimits.h"

#include <cmath>
#include <initializer_list>
#include <limits>
#include <sstream>

namespace shadelab
{

namespace
{
std::string formatted(double x)
{
  std::ostringstream s;
  s << x;
  return s.str();
}

/// numberProblem() for the value at @p path, "" or "path: problem".
std::string problemAt(const std::string& path, double x, double lo, double hi, bool openLo = false)
{
  const std::string p = numberProblem(x, lo, hi, openLo);
  return p.empty() ? p : path + ": " + p;
}

std::string vectorProblem(const std::string& path, const glm::vec3& v, double lo, double hi)
{
  for (int i = 0; i < 3; ++i)
  {
    const std::string p = problemAt(path + "[" + std::to_string(i) + "]", v[i], lo, hi);
    if (!p.empty())
    {
      return p;
    }
  }
  return "";
}

/// The first non-empty problem of @p problems, or "".
std::string firstProblem(std::initializer_list<std::string> problems)
{
  for (const std::string& p : problems)
  {
    if (!p.empty())
    {
      return p;
    }
  }
  return "";
}

/// The values a scene file accepts for the light's type (the others are
/// never used for it).
std::string lightProblem(const SceneLight& l, const std::string& path)
{
  const std::string typeProblem = lightTypeValueProblem(static_cast<int>(l.type));
  if (!typeProblem.empty())
  {
    return path + ".type: " + typeProblem;
  }
  const bool positional = l.type == LightType::Point || l.type == LightType::Spot;
  const bool aimed = l.type == LightType::Directional || l.type == LightType::Spot;
  const bool spot = l.type == LightType::Spot;
  return firstProblem({ vectorProblem(path + ".ambient", l.ambient, 0.0, kMaxColourValue),
    vectorProblem(path + ".diffuse", l.diffuse, 0.0, kMaxColourValue),
    vectorProblem(path + ".specular", l.specular, 0.0, kMaxColourValue),
    problemAt(path + ".intensity", l.intensity, 0.0, kMaxColourValue),
    positional ? vectorProblem(path + ".position", l.position, -HUGE_VAL, HUGE_VAL) : "",
    positional ? vectorProblem(path + ".attenuation", l.attenuation, 0.0, HUGE_VAL) : "",
    aimed ? vectorProblem(path + ".direction", l.direction, -HUGE_VAL, HUGE_VAL) : "",
    spot ? problemAt(path + ".cutoff", l.cutoffDegrees, 0.0, 90.0, true) : "",
    spot ? problemAt(path + ".exponent", l.exponent, 0.0, kMaxSpotExponent) : "",
    spot ? problemAt(path + ".edge", l.edgeDegrees, 0.0, l.cutoffDegrees) : "" });
}
} // namespace

std::string numberProblem(double x, double lo, double hi, bool openLo, bool openHi)
{
  if (!std::isfinite(x))
  {
    return formatted(x) + " is not a finite number";
  }
  if (std::abs(x) > std::numeric_limits<float>::max())
  {
    return formatted(x) + " is beyond the float range";
  }
  if (x < lo || x > hi || (openLo && x == lo) || (openHi && x == hi))
  {
    return formatted(x) + " is out of range " + (openLo ? "(" : "[") + formatted(lo) + ", " +
      (std::isinf(hi) ? std::string("inf") : formatted(hi)) + (openHi || std::isinf(hi) ? ")" : "]");
  }
  return "";
}

std::string sceneValueProblem(const Scene& scene)
{
  const std::string modelProblem = modelValueProblem(static_cast<int>(scene.model));
  if (!modelProblem.empty())
  {
    return "shading.model: " + modelProblem;
  }
  for (size_t i = 0; i < scene.lights.size(); ++i)
  {
    const SceneLight& l = scene.lights[i];
    const std::string p =
      lightProblem(l, "lights[" + std::to_string(i) + "]" + (l.name.empty() ? "" : " (\"" + l.name + "\")"));
    if (!p.empty())
    {
      return p;
    }
  }
  const SceneMaterial& m = scene.material;
  return firstProblem({ vectorProblem("material.ambient", m.ambient, 0.0, kMaxColourValue),
    vectorProblem("material.diffuse", m.diffuse, 0.0, kMaxColourValue),
    vectorProblem("material.specular", m.specular, 0.0, kMaxColourValue),
    vectorProblem("material.emission", m.emission, 0.0, kMaxColourValue),
    problemAt("material.shininess", m.shininess, 0.0, kMaxShininess),
    vectorProblem("camera.position", scene.camera.position, -HUGE_VAL, HUGE_VAL),
    vectorProblem("camera.focalPoint", scene.camera.focalPoint, -HUGE_VAL, HUGE_VAL) });
}

} // namespace shadelab
