#ifndef shadelab_SceneKeys_h
#define shadelab_SceneKeys_h
/**
 * @file SceneKeys.h
 * @brief The one declaration of the scene-file keys of lights, materials and
 * cameras: each key's name, kind, range, default, which light types take it
 * and which field it fills. The scene reader and writer (SceneFile.cxx), the
 * range check of scenes built in code (SceneLimits.cxx) and the JSON schema
 * (generator/GenerateSceneSchema.cxx) all go through these tables. The
 * light keys are the rows of SHADELAB_LIGHT_KEYS (LightingTables.h).
 *
 * Defaults are those of a default-constructed SceneMaterial and SceneCamera,
 * and defaultLight() for lights.
 */

#include "shadelab/LightingTables.h"
#include "shadelab/Scene.h"

#include <string>
#include <vector>

namespace shadelab
{

/// One key of the object @p Struct (SceneLight, SceneMaterial, SceneBrdf, SceneCamera).
/// Exactly one of the field pointers is set, the one of its kind.
template <typename Struct>
struct SceneKey
{
  const char* name;
  SceneKeyKind kind;
  /// Lights: the parameter a light type must take to take this key
  /// (LightingTables.h); 0: every light takes it.
  unsigned lightParameter = 0;
  /// Materials: the MaterialParameterBit of the key (LightingTables.h); a
  /// model whose row reads it is changed by it (editors show it for those).
  unsigned materialParameter = 0;
  double lo = 0.0, hi = 0.0; ///< range of a number (and of each component of a colour)
  bool openLo = false, openHi = false;
  /// When set, hi is this field's value (a spot's edge is at most its cutoff).
  float Struct::*upTo = nullptr;
  /// Text: the problem of an empty string, or null if it may be empty.
  const char* whenEmpty = nullptr;
  float Struct::*number = nullptr;
  glm::vec3 Struct::*vector = nullptr;
  std::string Struct::*text = nullptr;
  LightSpace Struct::*space = nullptr;
  std::vector<std::string> Struct::*parameters = nullptr;
  /// What the key means, for the JSON schema (null: nothing to add).
  const char* what = nullptr;
};

/// The keys of a light besides "type" (read first, it decides the others):
/// the rows of SHADELAB_LIGHT_KEYS (LightingTables.h).
const std::vector<SceneKey<SceneLight>>& lightKeys();
/// The keys of "material".
const std::vector<SceneKey<SceneMaterial>>& materialKeys();
/// The keys of "brdf" (a .brdf file and its parameter values).
const std::vector<SceneKey<SceneBrdf>>& brdfKeys();
/// The keys of "camera". Only position and focalPoint are checked in scenes
/// built in code (sceneValueProblem); the others are the file format's.
const std::vector<SceneKey<SceneCamera>>& cameraKeys();

/// Whether a light of @p type takes @p key.
bool lightTakesKey(LightType type, const SceneKey<SceneLight>& key);

/// A light of @p type with every value at its default. A type that takes no
/// diffuse colour lights k_a only: its ambient colour is white and its
/// diffuse and specular colours are zero.
SceneLight defaultLight(LightType type);

/// "" if @p direction has a length above 0 (in float, as it is used);
/// else "a direction must not have zero length". Scene files and
/// keyValueProblem() both ask it.
std::string directionProblem(const glm::vec3& direction);

/// "" if @p object's value for @p key is finite and in range, and a
/// direction not of zero length; else "PATH.KEY[i]: problem"
/// (numberProblem()'s wording) or "PATH.KEY: problem" (directionProblem()).
/// Text and space keys have no problem here.
template <typename Struct>
std::string keyValueProblem(const SceneKey<Struct>& key, const Struct& object, const std::string& path);

/// The upper end of @p key's range for @p object (upTo's value if set).
template <typename Struct>
double keyUpperLimit(const SceneKey<Struct>& key, const Struct& object)
{
  return key.upTo ? static_cast<double>(object.*(key.upTo)) : key.hi;
}

} // namespace shadelab

#endif
