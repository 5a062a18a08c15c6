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
/// The range column of SHADELAB_LIGHT_KEYS and SHADELAB_MATERIAL_PARAMETERS.
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

namespace
{
using M = SceneMaterial;
/// The key of SceneMaterial member @p field (a colour or a number).
SceneKey<M> materialKey(const char* name, float M::*field, unsigned bit, LightKeyRange range)
{
  SceneKey<M> k = numberKey(name, field, range.lo, range.hi, range.openLo, range.openHi);
  k.materialParameter = bit;
  return k;
}
SceneKey<M> materialKey(const char* name, glm::vec3 M::*field, unsigned bit, LightKeyRange)
{
  SceneKey<M> k = vectorKey(name, SceneKeyKind::Colour, field);
  k.materialParameter = bit;
  return k;
}
} // namespace

const std::vector<SceneKey<SceneMaterial>>& materialKeys()
{
  static const std::vector<SceneKey<M>> keys = [] {
    std::vector<SceneKey<M>> out;
#define SHADELAB_KEY(type, field, bit, name, value, range, meaning)                                                   \
  out.push_back(described(materialKey(name, &M::field, bit, range), meaning));
    SHADELAB_MATERIAL_PARAMETERS(SHADELAB_KEY)
#undef SHADELAB_KEY
    out.push_back(described(textKey("diffuseTexture", &M::diffuseTexture, "must name an image file"),
      "Image (any OpenImageIO format) used as k_d through the mesh's texture coordinates; relative to the scene "
      "file."));
    out.back().materialParameter = kReadsDiffuse;
    return out;
  }();
  return keys;
}

const std::vector<SceneKey<SceneBrdf>>& brdfKeys()
{
  using B = SceneBrdf;
  static const std::vector<SceneKey<B>> keys = [] {
    SceneKey<B> parameters{ "parameters", SceneKeyKind::Parameters };
    parameters.parameters = &B::parameters;
    return std::vector<SceneKey<B>>{ described(textKey("file", &B::file, "must name a .brdf file"),
                                       "BRDF Explorer .brdf file shading in place of the model's diffuse and "
                                       "specular factors; relative to the scene file."),
      described(parameters,
        "Values of the file's parameters by name: a number (float), true/false (bool) or [r, g, b] (color); "
        "the file's defaults hold for the others.") };
  }();
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

std::string directionProblem(const glm::vec3& direction)
{
  return glm::length(direction) > 0.0f ? "" : "a direction must not have zero length";
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
    if (key.kind == SceneKeyKind::Direction)
    {
      const std::string p = directionProblem(v);
      return p.empty() ? p : at + ": " + p;
    }
  }
  return "";
}

template std::string keyValueProblem(const SceneKey<SceneLight>&, const SceneLight&, const std::string&);
template std::string keyValueProblem(const SceneKey<SceneMaterial>&, const SceneMaterial&, const std::string&);
template std::string keyValueProblem(const SceneKey<SceneBrdf>&, const SceneBrdf&, const std::string&);
template std::string keyValueProblem(const SceneKey<SceneCamera>&, const SceneCamera&, const std::string&);

} // namespace shadelab
