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

template <typename S>
SceneKey<S> described(SceneKey<S> key, const char* what)
{
  key.what = what;
  return key;
}

std::string indexed(const std::string& path, int i)
{
  return path + "[" + std::to_string(i) + "]";
}
} // namespace

namespace
{
/// The range column of SHADELAB_LIGHT_KEYS.
struct LightKeyRange
{
  double lo = 0.0, hi = 0.0;
  bool openLo = false, openHi = false;
  bool upToCutoff = false;
  bool byKind = false; ///< the kind's own range (vectorKey())
};
LightKeyRange anyValue()
{
  LightKeyRange r;
  r.byKind = true;
  return r;
}
LightKeyRange closed(double lo, double hi)
{
  LightKeyRange r;
  r.lo = lo;
  r.hi = hi;
  return r;
}
LightKeyRange openBelow(double lo, double hi)
{
  LightKeyRange r = closed(lo, hi);
  r.openLo = true;
  return r;
}
/// [lo, hi], and at most the light's cutoff (a spot's edge).
LightKeyRange upToCutoff(double lo, double hi)
{
  LightKeyRange r = closed(lo, hi);
  r.upToCutoff = true;
  return r;
}

using L = SceneLight;

/// The key of SceneLight member @p field, whose C++ type picks the field pointer.
SceneKey<L> lightKey(const char* name, SceneKeyKind, float L::*field, unsigned parameter, LightKeyRange range)
{
  SceneKey<L> k = numberKey(name, field, range.lo, range.hi, range.openLo, range.openHi, parameter);
  k.upTo = range.upToCutoff ? &L::cutoffDegrees : nullptr;
  return k;
}
SceneKey<L> lightKey(const char* name, SceneKeyKind kind, glm::vec3 L::*field, unsigned parameter, LightKeyRange)
{
  return vectorKey(name, kind, field, parameter);
}
SceneKey<L> lightKey(const char* name, SceneKeyKind, std::string L::*field, unsigned parameter, LightKeyRange)
{
  SceneKey<L> k = textKey(name, field);
  k.lightParameter = parameter;
  return k;
}
SceneKey<L> lightKey(const char* name, SceneKeyKind kind, LightSpace L::*field, unsigned parameter, LightKeyRange)
{
  SceneKey<L> k{ name, kind, parameter };
  k.space = field;
  return k;
}
} // namespace

const std::vector<SceneKey<SceneLight>>& lightKeys()
{
  static const std::vector<SceneKey<L>> keys = [] {
    std::vector<SceneKey<L>> out;
#define SHADELAB_KEY(member, name, Kind, value, parameter, range, meaning)                                            \
  out.push_back(lightKey(name, SceneKeyKind::Kind, &L::member, parameter, range));                                   \
  out.back().what = meaning;
    SHADELAB_LIGHT_KEYS(SHADELAB_KEY)
#undef SHADELAB_KEY
    return out;
  }();
  return keys;
}

const std::vector<SceneKey<SceneMaterial>>& materialKeys()
{
  using M = SceneMaterial;
  static const std::vector<SceneKey<M>> keys{
    described(vectorKey("ambient", SceneKeyKind::Colour, &M::ambient), "k_a"),
    described(vectorKey("diffuse", SceneKeyKind::Colour, &M::diffuse), "k_d"),
    described(vectorKey("specular", SceneKeyKind::Colour, &M::specular), "k_s"),
    described(vectorKey("emission", SceneKeyKind::Colour, &M::emission), "k_e"),
    described(numberKey("shininess", &M::shininess, 0.0, kMaxShininess), "n, the specular exponent"),
    described(textKey("diffuseTexture", &M::diffuseTexture, "must name an image file"),
      "Image (any OpenImageIO format) used as k_d through the mesh's texture coordinates; relative to the scene "
      "file.") };
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
