#include "shadelab/SceneLimits.h"

#include <cmath>
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

/// "" if @p x is finite and in [lo, hi], else the problem for @p path.
std::string numberProblem(const std::string& path, double x, double lo, double hi)
{
  if (!std::isfinite(x))
  {
    return path + ": " + formatted(x) + " is not a finite number";
  }
  if (x < lo || x > hi)
  {
    return path + ": " + formatted(x) + " is out of range [" + formatted(lo) + ", " + formatted(hi) + "]";
  }
  return "";
}

std::string vectorProblem(const std::string& path, const glm::vec3& v, double lo, double hi)
{
  for (int i = 0; i < 3; ++i)
  {
    const std::string p = numberProblem(path + "[" + std::to_string(i) + "]", v[i], lo, hi);
    if (!p.empty())
    {
      return p;
    }
  }
  return "";
}

std::string lightProblem(const SceneLight& l, const std::string& path)
{
  const double big = HUGE_VAL;
  const std::pair<const char*, const glm::vec3*> colours[] = { { "ambient", &l.ambient },
    { "diffuse", &l.diffuse }, { "specular", &l.specular } };
  for (const auto& c : colours)
  {
    const std::string p = vectorProblem(path + "." + c.first, *c.second, 0.0, kMaxColourValue);
    if (!p.empty())
    {
      return p;
    }
  }
  for (const std::string& p : { numberProblem(path + ".intensity", l.intensity, 0.0, kMaxColourValue),
         vectorProblem(path + ".position", l.position, -big, big),
         vectorProblem(path + ".direction", l.direction, -big, big),
         vectorProblem(path + ".attenuation", l.attenuation, 0.0, big),
         numberProblem(path + ".cutoff", l.cutoffDegrees, 0.0, 90.0),
         numberProblem(path + ".exponent", l.exponent, 0.0, kMaxSpotExponent),
         numberProblem(path + ".edge", l.edgeDegrees, 0.0, 90.0) })
  {
    if (!p.empty())
    {
      return p;
    }
  }
  return "";
}
} // namespace

std::string sceneValueProblem(const Scene& scene)
{
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
  for (const std::string& p : { vectorProblem("material.ambient", m.ambient, 0.0, kMaxColourValue),
         vectorProblem("material.diffuse", m.diffuse, 0.0, kMaxColourValue),
         vectorProblem("material.specular", m.specular, 0.0, kMaxColourValue),
         vectorProblem("material.emission", m.emission, 0.0, kMaxColourValue),
         numberProblem("material.shininess", m.shininess, 0.0, kMaxShininess),
         vectorProblem("camera.position", scene.camera.position, -HUGE_VAL, HUGE_VAL),
         vectorProblem("camera.focalPoint", scene.camera.focalPoint, -HUGE_VAL, HUGE_VAL) })
  {
    if (!p.empty())
    {
      return p;
    }
  }
  return "";
}

} // namespace shadelab
