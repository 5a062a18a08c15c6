#ifndef shadelab_LightingTables_h
#define shadelab_LightingTables_h
/**
 * @file LightingTables.h
 * @brief The one declaration of ShadeLab's lighting models, light types and
 * material parameters. Everything else derives from these tables: the
 * SL_MODEL_* and SL_LIGHT_* constants of slLighting.glsl (generated from here
 * at build time, see GenerateGLSLTables.cxx), the C++ enums below, the name
 * lists of Scene.h, the scene keys (SceneKeys.h), the JSON schema and the
 * ParaView plugin's model menus (generated at build time), the
 * command line's and the viewer's choices, and every dispatch over a model or
 * a light type (an X-macro expansion, so a new row is a new case).
 *
 * Header only, no dependencies: the build's GLSL generator includes it too.
 *
 * A row's position is its value (the enum value, the GLSL constant, the index
 * in the name lists). Adding a lighting model: one row here, its formula in
 * slLighting.glsl, its expected values in tests/core/TableExpectations.h.
 * Adding a light type: the same three files (a new parameter: its bit, its
 * key row and the evaluated field it feeds, all here).
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
  kReadsShininess = 1u << 4,
  kReadsRoughness = 1u << 5,
  kReadsRoughnessPair = 1u << 6, ///< the anisotropic pair along the tangent X and Y = N x X
  kReadsIor = 1u << 7
};

/// The shape of a model's specular lobe, for the CPU integrators that sample
/// or split it (Albedo.cxx, RadianceEstimator.cxx): none, a power of the
/// cosine around the mirror direction R (Phong) or of the normal's cosine
/// with the half vector H (Blinn-Phong), or a microfacet distribution of H:
/// GGX (Trowbridge-Reitz), Beckmann, Ward's anisotropic Gaussian, or
/// Ashikhmin-Shirley's anisotropic power of N.H.
enum class SpecularLobe
{
  None,
  Mirror,
  Halfway,
  GGX,
  Beckmann,
  Ward,
  AshikhminShirley
};

// clang-format off
/// Material parameters: the fields of slMaterial (generated into
/// slLightingTables.glsl), the members of SceneMaterial (Scene.h) and the
/// keys of a scene file's "material" (SceneKeys.h: reader, writer, range
/// checks, JSON schema). X(GLSL type: vec3 is a colour, float a number,
/// field, bit, "key", default, range (SceneKeys.cxx: anyValue() for a
/// colour, closed(lo, hi)), "what it means").
#define SHADELAB_MATERIAL_PARAMETERS(X)                                                                               \
  X(vec3, ambient, kReadsAmbient, "ambient", glm::vec3(0.1f), anyValue(), "k_a, reflects the lights' ambient colours") \
  X(vec3, diffuse, kReadsDiffuse, "diffuse", glm::vec3(0.8f), anyValue(), "k_d")                                      \
  X(vec3, specular, kReadsSpecular, "specular", glm::vec3(0.5f), anyValue(), "k_s")                                   \
  X(vec3, emission, kReadsEmission, "emission", glm::vec3(0.0f), anyValue(), "k_e, added once per point")             \
  X(float, shininess, kReadsShininess, "shininess", 32.0f, closed(0.0, kMaxShininess), "n, the specular exponent")   \
  X(float, roughness, kReadsRoughness, "roughness", 0.3f, closed(0.0, 1.0),                                           \
    "alpha, the width of GGX and Beckmann (Beckmann's RMS facet slope; at least 0.01 in the formulas); "          \
    "Oren-Nayar's sigma in radians (0: Lambert)")                                                                                 \
  X(float, roughnessX, kReadsRoughnessPair, "roughnessX", 0.15f, closed(0.0, 1.0),                                    \
    "alpha along the tangent X (Ward, Ashikhmin-Shirley; at least 0.01 in the formulas)")                            \
  X(float, roughnessY, kReadsRoughnessPair, "roughnessY", 0.45f, closed(0.0, 1.0),                                    \
    "alpha along the bitangent Y = N x X (Ward, Ashikhmin-Shirley; at least 0.01 in the formulas)")                  \
  X(float, ior, kReadsIor, "ior", 1.5f, closed(1.0, 10.0),                                                            \
    "index of refraction: Schlick's Fresnel F0 = ((ior - 1) / (ior + 1))^2")

/// Lighting models. X(Enumerator, GLSL_SUFFIX, "scene-file name", normalised,
/// material parameters read, specular lobe). GLSL: SL_MODEL_<GLSL_SUFFIX>.
/// A model that reads kReadsRoughnessPair is anisotropic: it needs the
/// mesh's tangents (modelNeedsTangents()).
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
    kReadsAmbient | kReadsDiffuse | kReadsSpecular | kReadsEmission | kReadsShininess, SpecularLobe::Halfway)         \
  X(CookTorranceGGX, COOK_TORRANCE_GGX, "cook-torrance-ggx", true,                                                    \
    kReadsAmbient | kReadsDiffuse | kReadsSpecular | kReadsEmission | kReadsRoughness | kReadsIor, SpecularLobe::GGX) \
  X(CookTorranceBeckmann, COOK_TORRANCE_BECKMANN, "cook-torrance-beckmann", true,                                     \
    kReadsAmbient | kReadsDiffuse | kReadsSpecular | kReadsEmission | kReadsRoughness | kReadsIor,                    \
    SpecularLobe::Beckmann)                                                                                           \
  X(OrenNayar, OREN_NAYAR, "oren-nayar", true,                                                                        \
    kReadsAmbient | kReadsDiffuse | kReadsEmission | kReadsRoughness, SpecularLobe::None)                             \
  X(Ward, WARD, "ward", true,                                                                                         \
    kReadsAmbient | kReadsDiffuse | kReadsSpecular | kReadsEmission | kReadsRoughnessPair, SpecularLobe::Ward)        \
  X(AshikhminShirley, ASHIKHMIN_SHIRLEY, "ashikhmin-shirley", true,                                                   \
    kReadsAmbient | kReadsDiffuse | kReadsSpecular | kReadsEmission | kReadsRoughnessPair | kReadsIor,                \
    SpecularLobe::AshikhminShirley)

/// The values a light type can take besides its name, type, intensity and
/// ambient colour (which every light has). A light-type row names its own;
/// SHADELAB_LIGHT_KEYS below says how each is written in a scene file.
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
/// (generated into slLightingTables.glsl), each computed from a SceneLight's
/// members (see SHADELAB_LIGHT_KEYS) by toEvaluationLight(), copied field by
/// field into the CPU kernel's batches and uploaded field by field as the
/// render pass's uniforms. X(GLSL type: int, float or vec3, field, what, its
/// value: an expression of the SceneLight `light`).
#define SHADELAB_LIGHT_FIELDS(X)                                                                                      \
  X(int, type, "SL_LIGHT_*", static_cast<int>(light.type))                                                            \
  X(vec3, position, "point and spot lights", light.position)                                                          \
  X(vec3, direction, "unit vector the light travels along (directional, spot)",                                       \
    glsl::slSafeNormalize(light.direction))                                                                           \
  X(vec3, ambient, "per-light ambient colour (OpenGL style)", light.ambient)                                          \
  X(vec3, diffuse, "per-light diffuse colour", light.diffuse)                                                         \
  X(vec3, specular, "per-light specular colour", light.specular)                                                      \
  X(float, intensity, "scales all three colours", light.intensity)                                                    \
  X(vec3, attenuation, "c1, c2, c3 of min(1, 1 / (c1 + c2 d + c3 d^2))", light.attenuation)                           \
  X(float, cosCutoff, "spot: cosine of the cutoff half-angle", glm::cos(glm::radians(light.cutoffDegrees)))           \
  X(float, cosInner, "spot: cosine where the smooth edge ends (== cosCutoff: hard edge)",                             \
    light.edgeDegrees > 0.0f ? glm::cos(glm::radians(glm::max(light.cutoffDegrees - light.edgeDegrees, 0.0f)))       \
                             : glm::cos(glm::radians(light.cutoffDegrees)))                                           \
  X(float, exponent, "spot: cos^exponent falloff inside the cone", light.exponent)

/// The keys of a light in a scene file besides "type" (which every light has
/// and which decides the others), in reading order ("edge" after the
/// "cutoff" that bounds it): the members of SceneLight (Scene.h), the rows
/// of lightKeys() (SceneKeys.h) that the scene reader, writer, range checks
/// and JSON schema go through. X(SceneLight member, "key", SceneKeyKind,
/// default, the LightParameterBit a type must take to take the key (0u:
/// every type), range (SceneKeys.cxx: anyValue(), closed(lo, hi),
/// openBelow(lo, hi), upToCutoff(lo, hi)), "what it means").
#define SHADELAB_LIGHT_KEYS(X)                                                                                        \
  X(name, "name", Text, std::string(), 0u, anyValue(), "a label for messages and editors")                           \
  X(space, "space", Space, LightSpace::World, kLightSpace, anyValue(),                                                \
    "world, or camera: VTK's camera-light convention, camera at (0,0,1) looking at the origin, view up +y")          \
  X(intensity, "intensity", Number, 1.0f, 0u, closed(0.0, kMaxColourValue), "scales the light's colours")            \
  X(ambient, "ambient", Colour, glm::vec3(0.0f), 0u, anyValue(),                                                      \
    "per-light ambient colour (OpenGL style); an ambient light's colour")                                             \
  X(diffuse, "diffuse", Colour, glm::vec3(1.0f), kLightDiffuse, anyValue(), "per-light diffuse colour")               \
  X(specular, "specular", Colour, glm::vec3(1.0f), kLightSpecular, anyValue(), "per-light specular colour")           \
  X(position, "position", Point, glm::vec3(0.0f, 0.0f, 1.0f), kLightPosition, anyValue(), "where the light is")      \
  X(direction, "direction", Direction, glm::vec3(0.0f, 0.0f, -1.0f), kLightDirection, anyValue(),                     \
    "where the light travels (a spot's axis); any non-zero length, normalised on use")                               \
  X(attenuation, "attenuation", Coefficients, glm::vec3(1.0f, 0.0f, 0.0f), kLightAttenuation, anyValue(),             \
    "c1, c2, c3 of f_att = min(1, 1 / (c1 + c2 d + c3 d^2)); all zero means none")                                  \
  X(cutoffDegrees, "cutoff", Number, 30.0f, kLightCutoff, openBelow(0.0, 90.0), "half-angle of the cone, degrees")   \
  X(exponent, "exponent", Number, 0.0f, kLightExponent, closed(0.0, kMaxSpotExponent),                                \
    "cos^exponent falloff from the axis")                                                                             \
  X(edgeDegrees, "edge", Number, 0.0f, kLightEdge, upToCutoff(0.0, 90.0),                                             \
    "width in degrees of the smooth edge inside the cutoff, at most the cutoff; 0: hard edge")

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

/// Whether @p model is anisotropic: its formula reads the tangent X of the
/// surface, so a mesh shaded with it must carry "Tangents".
constexpr bool modelNeedsTangents(ShadingModel model)
{
  return (modelInfo(model).reads & kReadsRoughnessPair) != 0;
}

/// The grey k_d and k_s that show @p model's own reflection at unit
/// strength: k_d = 1 for a model without a specular term (lambert,
/// lambert-normalized, oren-nayar), else k_s = 1 and k_d = 0. The albedo
/// table's material, and a lobe's weights unless they are given.
struct UnitWeights
{
  float diffuse, specular;
};
constexpr UnitWeights unitWeights(ShadingModel model)
{
  return (modelInfo(model).reads & kReadsSpecular) != 0 ? UnitWeights{ 0.0f, 1.0f } : UnitWeights{ 1.0f, 0.0f };
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
