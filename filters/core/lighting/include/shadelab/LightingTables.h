#ifndef shadelab_LightingTables_h
#define shadelab_LightingTables_h
/**
 * @file LightingTables.h
 * @brief The one declaration of ShadeLab's lighting models, light types and
 * material parameters. Everything else derives from these tables: the
 * SL_MODEL_* and SL_LIGHT_* constants of slLighting.glsl (generated from here
 * at build time, see GenerateGLSLTables.cxx), the C++ enums below, the name
 * lists of Scene.h, the scene keys (SceneKeys.h), the JSON schema test, the
 * command line's and the viewer's choices, and every dispatch over a model or
 * a light type (an X-macro expansion, so a new row is a new case).
 *
 * Header only, no dependencies: the build's GLSL generator includes it too.
 *
 * A row's position is its value (the enum value, the GLSL constant, the index
 * in the name lists). Adding a lighting model: one row here, its formula in
 * slLighting.glsl, its expected values in tests/core/ModelExpectations.h.
 */

namespace shadelab
{

/// The material coefficients a lighting model can read; a model row names
/// those its formula uses (the others do not change its result).
enum MaterialParameterBit : unsigned
{
  kReadsAmbient = 1u << 0,
  kReadsDiffuse = 1u << 1,
  kReadsSpecular = 1u << 2,
  kReadsEmission = 1u << 3,
  kReadsShininess = 1u << 4
};

/// The shape of a model's specular lobe, for the CPU integrators that sample
/// or split it (Albedo.cxx, RadianceEstimator.cxx): none, around the mirror
/// direction R, or around the normal in the half-vector H.
enum class SpecularLobe
{
  None,
  Mirror,
  Halfway
};

// clang-format off
/// Material parameters: the fields of slMaterial (generated into
/// slLightingTables.glsl) and of SceneMaterial. X(GLSL type, field, bit, what).
#define SHADELAB_MATERIAL_PARAMETERS(X)                                                                               \
  X(vec3, ambient, kReadsAmbient, "k_a, reflects the lights' ambient colours")                                        \
  X(vec3, diffuse, kReadsDiffuse, "k_d")                                                                              \
  X(vec3, specular, kReadsSpecular, "k_s")                                                                            \
  X(vec3, emission, kReadsEmission, "k_e, added once per point")                                                     \
  X(float, shininess, kReadsShininess, "n, the specular exponent")

/// Lighting models. X(Enumerator, GLSL_SUFFIX, "scene-file name", normalised,
/// material parameters read, specular lobe). GLSL: SL_MODEL_<GLSL_SUFFIX>.
#define SHADELAB_LIGHTING_MODELS(X)                                                                                  \
  X(Lambert, LAMBERT, "lambert", false,                                                                               \
    kReadsAmbient | kReadsDiffuse | kReadsEmission, SpecularLobe::None)                                               \
  X(Phong, PHONG, "phong", false,                                                                                     \
    kReadsAmbient | kReadsDiffuse | kReadsSpecular | kReadsEmission | kReadsShininess, SpecularLobe::Mirror)          \
  X(BlinnPhong, BLINN_PHONG, "blinn-phong", false,                                                                    \
    kReadsAmbient | kReadsDiffuse | kReadsSpecular | kReadsEmission | kReadsShininess, SpecularLobe::Halfway)         \
  X(LambertNormalized, LAMBERT_NORMALIZED, "lambert-normalized", true,                                                \
    kReadsAmbient | kReadsDiffuse | kReadsEmission, SpecularLobe::None)                                               \
  X(PhongNormalized, PHONG_NORMALIZED, "phong-normalized", true,                                                      \
    kReadsAmbient | kReadsDiffuse | kReadsSpecular | kReadsEmission | kReadsShininess, SpecularLobe::Mirror)          \
  X(BlinnPhongNormalized, BLINN_PHONG_NORMALIZED, "blinn-phong-normalized", true,                                     \
    kReadsAmbient | kReadsDiffuse | kReadsSpecular | kReadsEmission | kReadsShininess, SpecularLobe::Halfway)

/// The values a light type can take besides its name, type, intensity and
/// ambient colour (which every light has). A light-type row names its own;
/// SceneKeys.h says how each is written in a scene file.
enum LightParameterBit : unsigned
{
  kLightSpace = 1u << 0,       ///< world or camera coordinates
  kLightPosition = 1u << 1,
  kLightDirection = 1u << 2,
  kLightDiffuse = 1u << 3,     ///< diffuse and specular colours: the light has a direction
  kLightSpecular = 1u << 4,
  kLightAttenuation = 1u << 5,
  kLightCutoff = 1u << 6,
  kLightExponent = 1u << 7,
  kLightEdge = 1u << 8
};

/// The light as the lighting equation evaluates it: the fields of slLight
/// (generated into slLightingTables.glsl), set from a SceneLight by
/// toEvaluationLight(), copied field by field into the CPU kernel's batches
/// and uploaded field by field as the render pass's uniforms.
/// X(GLSL type: int, float or vec3, field, what).
#define SHADELAB_LIGHT_FIELDS(X)                                                                                      \
  X(int, type, "SL_LIGHT_*")                                                                                          \
  X(vec3, position, "point and spot lights")                                                                          \
  X(vec3, direction, "unit vector the light travels along (directional, spot)")                                       \
  X(vec3, ambient, "per-light ambient colour (OpenGL style)")                                                         \
  X(vec3, diffuse, "per-light diffuse colour")                                                                        \
  X(vec3, specular, "per-light specular colour")                                                                      \
  X(float, intensity, "scales all three colours")                                                                     \
  X(vec3, attenuation, "c1, c2, c3 of min(1, 1 / (c1 + c2 d + c3 d^2))")                                              \
  X(float, cosCutoff, "spot: cosine of the cutoff half-angle")                                                        \
  X(float, cosInner, "spot: cosine where the smooth edge ends (== cosCutoff: hard edge)")                             \
  X(float, exponent, "spot: cos^exponent falloff inside the cone")

/// Light types. X(Enumerator, GLSL_SUFFIX, "scene-file name", parameters).
/// GLSL: SL_LIGHT_<GLSL_SUFFIX>. A type without kLightDiffuse lights k_a
/// only: its ambient colour defaults to white (SceneKeys.h).
#define SHADELAB_LIGHT_TYPES(X)                                                                                       \
  X(Directional, DIRECTIONAL, "directional", kLightSpace | kLightDiffuse | kLightSpecular | kLightDirection)          \
  X(Point, POINT, "point", kLightSpace | kLightDiffuse | kLightSpecular | kLightPosition | kLightAttenuation)          \
  X(Spot, SPOT, "spot",                                                                                               \
    kLightSpace | kLightDiffuse | kLightSpecular | kLightPosition | kLightDirection | kLightAttenuation |             \
      kLightCutoff | kLightExponent | kLightEdge)                                                                     \
  X(Ambient, AMBIENT, "ambient", 0u)
// clang-format on

/// A lighting model; the value equals slLighting.glsl's SL_MODEL_* constant.
enum class ShadingModel
{
#define SHADELAB_ENUMERATOR(Enumerator, ...) Enumerator,
  SHADELAB_LIGHTING_MODELS(SHADELAB_ENUMERATOR)
#undef SHADELAB_ENUMERATOR
};

/// A light type; the value equals slLighting.glsl's SL_LIGHT_* constant.
enum class LightType
{
#define SHADELAB_ENUMERATOR(Enumerator, ...) Enumerator,
  SHADELAB_LIGHT_TYPES(SHADELAB_ENUMERATOR)
#undef SHADELAB_ENUMERATOR
};

/// One row of SHADELAB_LIGHTING_MODELS.
struct LightingModelInfo
{
  ShadingModel model;
  const char* glslName; ///< the constant's suffix: "BLINN_PHONG"
  const char* name;     ///< as written in scene files and on the command line
  bool normalized;      ///< energy-normalised BRDF (divides by pi, lobe normalised)
  unsigned reads;       ///< MaterialParameterBit set
  SpecularLobe lobe;
};

/// One row of SHADELAB_LIGHT_TYPES.
struct LightTypeInfo
{
  LightType type;
  const char* glslName;
  const char* name;
  unsigned parameters; ///< LightParameterBit set
};

inline constexpr LightingModelInfo kLightingModels[] = {
#define SHADELAB_ROW(Enumerator, GLSL, name, normalized, reads, lobe)                                                 \
  { ShadingModel::Enumerator, #GLSL, name, normalized, reads, lobe },
  SHADELAB_LIGHTING_MODELS(SHADELAB_ROW)
#undef SHADELAB_ROW
};

inline constexpr LightTypeInfo kLightTypes[] = {
#define SHADELAB_ROW(Enumerator, GLSL, name, parameters) { LightType::Enumerator, #GLSL, name, parameters },
  SHADELAB_LIGHT_TYPES(SHADELAB_ROW)
#undef SHADELAB_ROW
};

inline constexpr int kLightingModelCount = static_cast<int>(sizeof(kLightingModels) / sizeof(kLightingModels[0]));
inline constexpr int kLightTypeCount = static_cast<int>(sizeof(kLightTypes) / sizeof(kLightTypes[0]));

/// True if @p value is a row of the model table (an SL_MODEL_* value).
constexpr bool isLightingModel(int value)
{
  return value >= 0 && value < kLightingModelCount;
}
/// True if @p value is a row of the light-type table (an SL_LIGHT_* value).
constexpr bool isLightType(int value)
{
  return value >= 0 && value < kLightTypeCount;
}

/// The row of a model or light type; the value must be one (isLightingModel(),
/// isLightType(): every way in from outside checks it).
constexpr const LightingModelInfo& modelInfo(ShadingModel model)
{
  return kLightingModels[static_cast<int>(model)];
}
constexpr const LightTypeInfo& lightTypeInfo(LightType type)
{
  return kLightTypes[static_cast<int>(type)];
}

/// Whether a light of type @p type takes parameter @p bit.
constexpr bool lightTakes(LightType type, LightParameterBit bit)
{
  return (lightTypeInfo(type).parameters & bit) != 0;
}

/// Whether a light of SL_LIGHT_* type @p type arrives from a direction (it
/// has diffuse and specular colours), rather than lighting k_a only.
constexpr bool lightHasDirection(int type)
{
  return lightTakes(static_cast<LightType>(type), kLightDiffuse);
}

} // namespace shadelab

#endif
