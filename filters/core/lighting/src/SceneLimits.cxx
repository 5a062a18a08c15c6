#include "shadelab/SceneLimits.h"

#include "shadelab/SceneKeys.h"

#include <cmath>
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

/// The first problem of @p object's values for @p keys that @p checked
/// selects, or "".
template <typename Struct, typename Select>
std::string firstProblem(
  const std::vector<SceneKey<Struct>>& keys, const Struct& object, const std::string& path, Select checked)
{
  for (const SceneKey<Struct>& key : keys)
  {
    const std::string p = checked(key) ? keyValueProblem(key, object, path) : std::string();
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
  return firstProblem(lightKeys(), l, path, [&](const SceneKey<SceneLight>& key) { return lightTakesKey(l.type, key); });
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
  const std::string material =
    firstProblem(materialKeys(), scene.material, "material", [](const SceneKey<SceneMaterial>&) { return true; });
  if (!material.empty())
  {
    return material;
  }
  // A camera from VTK or code has no azimuth or elevation to check; its
  // position and focal point must be finite, its view-up a direction.
  return firstProblem(cameraKeys(), scene.camera, "camera", [](const SceneKey<SceneCamera>& key) {
    return key.kind == SceneKeyKind::Point || key.kind == SceneKeyKind::Direction;
  });
}

} // namespace shadelab
