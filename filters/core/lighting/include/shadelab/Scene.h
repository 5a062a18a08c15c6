#ifndef shadelab_Scene_h
#define shadelab_Scene_h
/**
 * @file Scene.h
 * @brief The ShadeLab scene as a user writes it: lights, material, camera,
 * lighting model, shading frequency, background and image size.
 *
 * Angles are in degrees and colours are linear RGB here, as in the JSON scene
 * files (docs/scene-format.md). toEvaluationLight() and
 * toEvaluationMaterial() turn them into the structs that the lighting
 * equation (slLighting.glsl) evaluates.
 */

#include "shadelab/LightingGLSL.h"
#include "shadelab/LightingTables.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace shadelab
{

/// World lights are fixed in the scene. Camera lights use VTK's camera-light
/// convention: coordinates relative to a camera at (0,0,1) looking at the
/// origin with view up (0,1,0), in units of the camera's distance.
enum class LightSpace
{
  World,
  Camera
};

/// Where lighting is evaluated: per face, per vertex, or per pixel.
enum class ShadingFrequency
{
  Flat,
  Gouraud,
  Phong
};

/// What a scene key holds and how it is checked (SceneKeys.h).
enum class SceneKeyKind
{
  Number,       ///< one number in [lo, hi]
  Colour,       ///< 3 numbers, each in [0, kMaxColourValue]
  Point,        ///< 3 finite numbers
  Direction,    ///< 3 finite numbers, not all zero
  Coefficients, ///< 3 numbers, each >= 0 (a light's attenuation)
  Text,         ///< a string (not empty when whenEmpty is set)
  Space,        ///< a LightSpace name
  Parameters    ///< an object of name: number, boolean or [r, g, b], kept as "name=value" texts
};

/// The C++ type of a key of kind K.
template <SceneKeyKind K>
struct SceneKeyValue
{
  using type = glm::vec3;
};
template <>
struct SceneKeyValue<SceneKeyKind::Number>
{
  using type = float;
};
template <>
struct SceneKeyValue<SceneKeyKind::Text>
{
  using type = std::string;
};
template <>
struct SceneKeyValue<SceneKeyKind::Space>
{
  using type = LightSpace;
};

/// A light: its type and one member per row of SHADELAB_LIGHT_KEYS
/// (LightingTables.h), with the row's default: name, space, position,
/// direction (where the light travels; not normalised), ambient, diffuse,
/// specular, intensity, attenuation (c1, c2, c3), cutoffDegrees (spot
/// half-angle, in (0, 90]), exponent (spot falloff, >= 0), edgeDegrees
/// (width of the smooth spot edge, in [0, cutoff]).
struct SceneLight
{
  LightType type = LightType::Directional;
#define SHADELAB_MEMBER(member, key, Kind, value, ...) SceneKeyValue<SceneKeyKind::Kind>::type member = value;
  SHADELAB_LIGHT_KEYS(SHADELAB_MEMBER)
#undef SHADELAB_MEMBER
};

/// The C++ type of a material parameter of GLSL type vec3 or float.
#define SHADELAB_MATERIAL_TYPE_vec3 glm::vec3
#define SHADELAB_MATERIAL_TYPE_float float

/// The material: one member per row of SHADELAB_MATERIAL_PARAMETERS
/// (LightingTables.h), with the row's default, and a diffuse texture.
struct SceneMaterial
{
#define SHADELAB_MEMBER(type, field, bit, key, value, ...) SHADELAB_MATERIAL_TYPE_##type field = value;
  SHADELAB_MATERIAL_PARAMETERS(SHADELAB_MEMBER)
#undef SHADELAB_MEMBER
  std::string diffuseTexture; ///< image for k_d, resolved against the scene file's folder
};

/// A BRDF Explorer .brdf file shading in place of the model's diffuse and
/// specular factors (shadelab/BrdfFile.h), and its parameter values.
struct SceneBrdf
{
  std::string file; ///< resolved against the scene file's folder; empty: the model
  /// "name=value" as `shadelab render --param` takes them (a colour "r,g,b",
  /// a bool 0 or 1); the file's defaults hold for the others.
  std::vector<std::string> parameters;
};

struct SceneCamera
{
  bool hasPosition = false; ///< false: fit the mesh in view, then apply azimuth/elevation
  glm::vec3 position{ 0.0f, 0.0f, 1.0f };
  glm::vec3 focalPoint{ 0.0f };
  glm::vec3 viewUp{ 0.0f, 1.0f, 0.0f };
  float viewAngle = 30.0f; ///< vertical, degrees
  float azimuth = 0.0f;    ///< degrees, applied after fitting
  float elevation = 0.0f;  ///< degrees, applied after fitting
};

struct Scene
{
  std::string description;
  std::vector<SceneLight> lights;
  SceneMaterial material;
  SceneBrdf brdf;
  SceneCamera camera;
  ShadingModel model = ShadingModel::BlinnPhong;
  ShadingFrequency frequency = ShadingFrequency::Phong;
  glm::vec3 background{ 0.1f, 0.1f, 0.12f };
  int width = 800;
  int height = 600;
  std::string sourceFile; ///< where it was read from; empty when built in code
};

/// The spelling used in scene files ("blinn-phong-normalized", "gouraud", ...);
/// for a value that is not one of the enum's, "(unknown lighting model 7)"
/// and the like (names of models and light types come from LightingTables.h).
const char* modelName(ShadingModel model);
const char* frequencyName(ShadingFrequency frequency);
const char* lightTypeName(LightType type);
const char* lightSpaceName(LightSpace space);

/// Every valid spelling, in enum order, for messages and the JSON schema.
const std::vector<std::string>& modelNames();
const std::vector<std::string>& frequencyNames();
const std::vector<std::string>& lightTypeNames();
const std::vector<std::string>& lightSpaceNames();

/// "" if @p value is a row of the model (light-type) table of
/// LightingTables.h; else the problem, for any way in that takes a number:
/// "7 is not a lighting model (0 lambert, 1 phong, ...)".
std::string modelValueProblem(int value);
std::string lightTypeValueProblem(int value);

/// "" if @p name spells a lighting model (a shading frequency); else the
/// problem, for any way in that takes a name: "\"Phong\" is not a
/// lighting model (lambert, phong, ...)" (a null name reads as "(null)").
std::string modelNameProblem(const char* name);
std::string frequencyNameProblem(const char* name);

/// Parse a spelling; returns false (leaving @p out alone) if it is not one.
bool parseModelName(const std::string& name, ShadingModel& out);
bool parseFrequencyName(const std::string& name, ShadingFrequency& out);
bool parseLightTypeName(const std::string& name, LightType& out);
bool parseLightSpaceName(const std::string& name, LightSpace& out);

/// The light as the lighting equation wants it: unit direction, cosines of
/// the spot angles. A camera-space light must first go through
/// lightInWorldSpace().
glsl::slLight toEvaluationLight(const SceneLight& light);

/// The material coefficients as the lighting equation wants them.
glsl::slMaterial toEvaluationMaterial(const SceneMaterial& material);

/// A camera-space light moved into world space for a camera at @p eye looking
/// at @p focalPoint with @p viewUp (VTK's camera-light transform). World lights
/// are returned unchanged.
SceneLight lightInWorldSpace(
  const SceneLight& light, const glm::vec3& eye, const glm::vec3& focalPoint, const glm::vec3& viewUp);

/// The inverse of lightInWorldSpace(): @p worldLight's position and direction
/// expressed in the camera space of the given camera, with space = Camera.
/// Editors use it to move a camera light with a widget drawn in world space.
SceneLight lightInCameraSpace(
  const SceneLight& worldLight, const glm::vec3& eye, const glm::vec3& focalPoint, const glm::vec3& viewUp);

} // namespace shadelab

#endif
