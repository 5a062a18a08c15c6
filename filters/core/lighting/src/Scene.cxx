#include "shadelab/Scene.h"

#include "shadelab/PrintableText.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>

namespace shadelab
{
namespace
{
template <typename Enum>
bool parseName(const std::vector<std::string>& names, const std::string& name, Enum& out)
{
  for (size_t i = 0; i < names.size(); ++i)
  {
    if (names[i] == name)
    {
      out = static_cast<Enum>(i);
      return true;
    }
  }
  return false;
}

/// The names of a table's rows, in row (= enum) order.
template <typename Row, size_t N>
std::vector<std::string> rowNames(const Row (&rows)[N])
{
  std::vector<std::string> names;
  for (const Row& row : rows)
  {
    names.emplace_back(row.name);
  }
  return names;
}

/// names[value], or "(unknown WHAT VALUE)" for a value outside the list,
/// kept so that the pointer stays valid.
const char* nameOf(const std::vector<std::string>& names, int value, const char* what)
{
  if (value >= 0 && static_cast<size_t>(value) < names.size())
  {
    return names[static_cast<size_t>(value)].c_str();
  }
  static thread_local std::string unknown;
  unknown = std::string("(unknown ") + what + " " + std::to_string(value) + ")";
  return unknown.c_str();
}
} // namespace

const std::vector<std::string>& modelNames()
{
  static const std::vector<std::string> names = rowNames(kLightingModels);
  return names;
}

const std::vector<std::string>& frequencyNames()
{
  static const std::vector<std::string> names{ "flat", "gouraud", "phong" };
  return names;
}

const std::vector<std::string>& lightTypeNames()
{
  static const std::vector<std::string> names = rowNames(kLightTypes);
  return names;
}

const std::vector<std::string>& lightSpaceNames()
{
  static const std::vector<std::string> names{ "world", "camera" };
  return names;
}

const char* modelName(ShadingModel model)
{
  return nameOf(modelNames(), static_cast<int>(model), "lighting model");
}
const char* frequencyName(ShadingFrequency frequency)
{
  return nameOf(frequencyNames(), static_cast<int>(frequency), "shading frequency");
}
const char* lightTypeName(LightType type)
{
  return nameOf(lightTypeNames(), static_cast<int>(type), "light type");
}
const char* lightSpaceName(LightSpace space)
{
  return nameOf(lightSpaceNames(), static_cast<int>(space), "light space");
}

namespace
{
std::string valueProblem(int value, const std::vector<std::string>& names, const char* what)
{
  if (value >= 0 && static_cast<size_t>(value) < names.size())
  {
    return "";
  }
  std::string list;
  for (size_t i = 0; i < names.size(); ++i)
  {
    list += (i ? ", " : "") + std::to_string(i) + " " + names[i];
  }
  return std::to_string(value) + " is not " + what + " (" + list + ")";
}

std::string nameProblem(const char* name, const std::vector<std::string>& names, const char* what)
{
  if (name && std::find(names.begin(), names.end(), name) != names.end())
  {
    return "";
  }
  std::string list;
  for (const std::string& known : names)
  {
    list += (list.empty() ? "" : ", ") + known;
  }
  return (name ? "\"" + printableText(name) + "\"" : std::string("(null)")) + " is not " + what + " (" + list + ")";
}
} // namespace

std::string modelValueProblem(int value)
{
  return valueProblem(value, modelNames(), "a lighting model");
}
std::string lightTypeValueProblem(int value)
{
  return valueProblem(value, lightTypeNames(), "a light type");
}

std::string modelNameProblem(const char* name)
{
  return nameProblem(name, modelNames(), "a lighting model");
}
std::string frequencyNameProblem(const char* name)
{
  return nameProblem(name, frequencyNames(), "a shading frequency");
}

bool parseModelName(const std::string& name, ShadingModel& out)
{
  return parseName(modelNames(), name, out);
}
bool parseFrequencyName(const std::string& name, ShadingFrequency& out)
{
  return parseName(frequencyNames(), name, out);
}
bool parseLightTypeName(const std::string& name, LightType& out)
{
  return parseName(lightTypeNames(), name, out);
}
bool parseLightSpaceName(const std::string& name, LightSpace& out)
{
  return parseName(lightSpaceNames(), name, out);
}

glsl::slLight toEvaluationLight(const SceneLight& light)
{
  glsl::slLight out;
#define SHADELAB_FIELD(type, field, what, value) out.field = value;
  SHADELAB_LIGHT_FIELDS(SHADELAB_FIELD)
#undef SHADELAB_FIELD
  return out;
}

glsl::slMaterial toEvaluationMaterial(const SceneMaterial& material)
{
  glsl::slMaterial out;
#define SHADELAB_COPY(type, field, ...) out.field = material.field;
  SHADELAB_MATERIAL_PARAMETERS(SHADELAB_COPY)
#undef SHADELAB_COPY
  return out;
}

namespace
{
/// VTK's camera-light frame: columns right, up, back (the camera looks along
/// -back); camera-light space puts the camera at (0,0,1) and the focal point
/// at the origin, one unit apart.
glm::mat3 cameraFrame(const glm::vec3& eye, const glm::vec3& focalPoint, const glm::vec3& viewUp)
{
  const glm::vec3 back = glsl::slSafeNormalize(eye - focalPoint);
  const glm::vec3 right = glsl::slSafeNormalize(glm::cross(viewUp, back));
  const glm::vec3 up = glm::cross(back, right);
  return glm::mat3(right, up, back);
}
} // namespace

SceneLight lightInWorldSpace(
  const SceneLight& light, const glm::vec3& eye, const glm::vec3& focalPoint, const glm::vec3& viewUp)
{
  if (light.space == LightSpace::World)
  {
    return light;
  }
  const glm::mat3 rotation = cameraFrame(eye, focalPoint, viewUp);
  SceneLight out = light;
  out.space = LightSpace::World;
  out.position = focalPoint + glm::length(eye - focalPoint) * (rotation * light.position);
  out.direction = rotation * light.direction;
  return out;
}

SceneLight lightInCameraSpace(
  const SceneLight& worldLight, const glm::vec3& eye, const glm::vec3& focalPoint, const glm::vec3& viewUp)
{
  // The frame is orthonormal, so its transpose is its inverse.
  const glm::mat3 toCamera = glm::transpose(cameraFrame(eye, focalPoint, viewUp));
  const float distance = glm::length(eye - focalPoint);
  SceneLight out = worldLight;
  out.space = LightSpace::Camera;
  out.position = toCamera * (worldLight.position - focalPoint) / (distance > 0.0f ? distance : 1.0f);
  out.direction = toCamera * worldLight.direction;
  return out;
}

} // namespace shadelab
