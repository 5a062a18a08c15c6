#include "shadelab/SceneKeys.h"

#include "shadelab/SceneLimits.h"

#include <cmath>

namespace shadelab
{
namespace
{
template <typename S>
SceneKey<S> numberKey(const char* name, float S::*field, double lo, double hi, bool openLo = false,
  bool openHi = false, unsigned parameter = 0)
{
  SceneKey<S> k{ name, SceneKeyKind::Number };
  k.number = field;
  k.lo = lo;
  k.hi = hi;
  k.openLo = openLo;
  k.openHi = openHi;
  k.lightParameter = parameter;
  return k;
}

template <typename S>
SceneKey<S> vectorKey(const char* name, SceneKeyKind kind, glm::vec3 S::*field, unsigned parameter = 0)
{
  SceneKey<S> k{ name, kind };
  k.vector = field;
  k.lightParameter = parameter;
  switch (kind)
  {
    case SceneKeyKind::Colour:
      k.hi = kMaxColourValue;
      break;
    case SceneKeyKind::Coefficients:
      k.hi = HUGE_VAL;
      break;
    default:
      k.lo = -HUGE_VAL;
      k.hi = HUGE_VAL;
      break;
  }
  return k;
}

template <typename S>
SceneKey<S> textKey(const char* name, std::string S::*field, const char* whenEmpty = nullptr)
{
  SceneKey<S> k{ name, SceneKeyKind::Text };
  k.text = field;
  k.whenEmpty = whenEmpty;
  return k;
}

std::string indexed(const std::string& path, int i)
{
  return path + "[" + std::to_string(i) + "]";
}
} // namespace

const std::vector<SceneKey<SceneLight>>& lightKeys()
{
  // In reading order: "edge" after the "cutoff" it is bounded by.
  static const std::vector<SceneKey<SceneLight>> keys = [] {
    using L = SceneLight;
    SceneKey<L> space{ "space", SceneKeyKind::Space, kLightSpace };
    space.space = &L::space;
    SceneKey<L> edge = numberKey("edge", &L::edgeDegrees, 0.0, 90.0, false, false, kLightEdge);
    edge.upTo = &L::cutoffDegrees;
    return std::vector<SceneKey<L>>{ textKey("name", &L::name), space,
      numberKey("intensity", &L::intensity, 0.0, kMaxColourValue),
      vectorKey("ambient", SceneKeyKind::Colour, &L::ambient),
      vectorKey("diffuse", SceneKeyKind::Colour, &L::diffuse, kLightDiffuse),
      vectorKey("specular", SceneKeyKind::Colour, &L::specular, kLightSpecular),
      vectorKey("position", SceneKeyKind::Point, &L::position, kLightPosition),
      vectorKey("direction", SceneKeyKind::Direction, &L::direction, kLightDirection),
      vectorKey("attenuation", SceneKeyKind::Coefficients, &L::attenuation, kLightAttenuation),
      numberKey("cutoff", &L::cutoffDegrees, 0.0, 90.0, true, false, kLightCutoff),
      numberKey("exponent", &L::exponent, 0.0, kMaxSpotExponent, false, false, kLightExponent), edge };
  }();
  return keys;
}

const std::vector<SceneKey<SceneMaterial>>& materialKeys()
{
  using M = SceneMaterial;
  static const std::vector<SceneKey<M>> keys{ vectorKey("ambient", SceneKeyKind::Colour, &M::ambient),
    vectorKey("diffuse", SceneKeyKind::Colour, &M::diffuse), vectorKey("specular", SceneKeyKind::Colour, &M::specular),
    vectorKey("emission", SceneKeyKind::Colour, &M::emission), numberKey("shininess", &M::shininess, 0.0, kMaxShininess),
    textKey("diffuseTexture", &M::diffuseTexture, "must name an image file") };
  return keys;
}

const std::vector<SceneKey<SceneCamera>>& cameraKeys()
{
  using C = SceneCamera;
  static const std::vector<SceneKey<C>> keys{ vectorKey("position", SceneKeyKind::Point, &C::position),
    vectorKey("focalPoint", SceneKeyKind::Point, &C::focalPoint),
    vectorKey("viewUp", SceneKeyKind::Direction, &C::viewUp), numberKey("viewAngle", &C::viewAngle, 0.0, 180.0, true, true),
    numberKey("azimuth", &C::azimuth, -360.0, 360.0), numberKey("elevation", &C::elevation, -90.0, 90.0, true, true) };
  return keys;
}

bool lightTakesKey(LightType type, const SceneKey<SceneLight>& key)
{
  return key.lightParameter == 0 || (lightTypeInfo(type).parameters & key.lightParameter) != 0;
}

SceneLight defaultLight(LightType type)
{
  SceneLight light;
  light.type = type;
  if (!lightTakes(type, kLightDiffuse))
  {
    light.ambient = glm::vec3(1.0f);
    light.diffuse = light.specular = glm::vec3(0.0f);
  }
  return light;
}

template <typename Struct>
std::string keyValueProblem(const SceneKey<Struct>& key, const Struct& object, const std::string& path)
{
  const std::string at = path + "." + key.name;
  if (key.number)
  {
    const std::string p =
      numberProblem(object.*(key.number), key.lo, keyUpperLimit(key, object), key.openLo, key.openHi);
    return p.empty() ? p : at + ": " + p;
  }
  if (key.vector)
  {
    const glm::vec3& v = object.*(key.vector);
    for (int i = 0; i < 3; ++i)
    {
      const std::string p = numberProblem(v[i], key.lo, key.hi, key.openLo, key.openHi);
      if (!p.empty())
      {
        return indexed(at, i) + ": " + p;
      }
    }
  }
  return "";
}

template std::string keyValueProblem(const SceneKey<SceneLight>&, const SceneLight&, const std::string&);
template std::string keyValueProblem(const SceneKey<SceneMaterial>&, const SceneMaterial&, const std::string&);
template std::string keyValueProblem(const SceneKey<SceneCamera>&, const SceneCamera&, const std::string&);

} // namespace shadelab
