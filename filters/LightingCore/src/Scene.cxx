#include "shadelab/Scene.h"

#include <glm/gtc/constants.hpp>

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
} // namespace

// The order of each list is the order of its enum (static_assert'ed below).
const std::vector<std::string>& modelNames()
{
  static const std::vector<std::string> names{ "lambert", "phong", "blinn-phong",
    "lambert-normalized", "phong-normalized", "blinn-phong-normalized" };
  return names;
}

const std::vector<std::string>& frequencyNames()
{
  static const std::vector<std::string> names{ "flat", "gouraud", "phong" };
  return names;
}

const std::vector<std::string>& lightTypeNames()
{
  static const std::vector<std::string> names{ "directional", "point", "spot", "ambient" };
  return names;
}

const std::vector<std::string>& lightSpaceNames()
{
  static const std::vector<std::string> names{ "world", "camera" };
  return names;
}

static_assert(static_cast<int>(ShadingModel::Lambert) == 0 &&
    static_cast<int>(ShadingModel::BlinnPhongNormalized) == 5,
  "modelNames() is indexed by ShadingModel");
static_assert(static_cast<int>(LightType::Directional) == 0 && static_cast<int>(LightType::Ambient) == 3,
  "lightTypeNames() is indexed by LightType");

const char* modelName(ShadingModel model)
{
  return modelNames()[static_cast<size_t>(model)].c_str();
}
const char* frequencyName(ShadingFrequency frequency)
{
  return frequencyNames()[static_cast<size_t>(frequency)].c_str();
}
const char* lightTypeName(LightType type)
{
  return lightTypeNames()[static_cast<size_t>(type)].c_str();
}
const char* lightSpaceName(LightSpace space)
{
  return lightSpaceNames()[static_cast<size_t>(space)].c_str();
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
  out.type = static_cast<int>(light.type);
  out.position = light.position;
  out.direction = glsl::slSafeNormalize(light.direction);
  out.ambient = light.ambient;
  out.diffuse = light.diffuse;
  out.specular = light.specular;
  out.intensity = light.intensity;
  out.attenuation = light.attenuation;
  const float cutoff = glm::radians(light.cutoffDegrees);
  const float inner = glm::radians(glm::max(light.cutoffDegrees - light.edgeDegrees, 0.0f));
  out.cosCutoff = glm::cos(cutoff);
  out.cosInner = light.edgeDegrees > 0.0f ? glm::cos(inner) : out.cosCutoff;
  out.exponent = light.exponent;
  return out;
}

glsl::slMaterial toEvaluationMaterial(const SceneMaterial& material)
{
  glsl::slMaterial out;
  out.ambient = material.ambient;
  out.diffuse = material.diffuse;
  out.specular = material.specular;
  out.emission = material.emission;
  out.shininess = material.shininess;
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
