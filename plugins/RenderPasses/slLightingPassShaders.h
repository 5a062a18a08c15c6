#ifndef slLightingPassShaders_h
#define slLightingPassShaders_h
/**
 * @file slLightingPassShaders.h
 * @brief The GLSL that slLightingPass splices into VTK's polydata shaders.
 *
 * Every lighting formula comes from slLighting.glsl (the lighting core's
 * single copy, see LightingShaderSource.h); what is here only loops over the
 * uniform lights, picks normals and positions for each shading frequency, and
 * composes the terms with the base colour. Internal to ShadeLab::RenderPasses.
 */

#include <string>
#include <vector>

namespace slLightingPassShaders
{

/// How many lights the shaders hold (uniform array size).
constexpr int MaximumLights = 16;

/// Frequencies, as in shadelab::ShadingFrequency.
enum Frequency
{
  Flat = 0,
  Gouraud = 1,
  Phong = 2
};

/// What is compiled into a shader variant: the frequency, the light count and
/// types (loops unroll, type tests fold) and the model (model tests fold).
struct Variant
{
  Frequency frequency = Phong;
  std::vector<int> lightTypes; ///< SL_LIGHT_* of each light
  int model = 0;               ///< SL_MODEL_*
  bool componentView = false;  ///< a component view, not the total
};

/// What the fragment shader has to work with, as found in VTK's shaders.
struct FragmentInputs
{
  bool scalarColors = false;    ///< diffuseColor carries point or cell scalars
  bool texture = false;         ///< actortexture and tcoordVCVSOutput exist
  bool mapperFaceNormal = false; ///< normalVCVSOutput is already per face (flat interpolation)
  bool tangentNormalMap = false; ///< normalTex + 4-component Tangents: ShadeLab maps the normal
};

/// Vertex-shader declarations and code passing 4-component tangents
/// (xyz, handedness w) to the fragment shader as slTangentVC.
std::string tangentVertexDeclarations();
std::string tangentVertexImplementation();

/// Declarations for either stage: the lighting core, the uniforms, helpers,
/// for the variant's lights and model.
std::string declarations(const Variant& variant);

/// Vertex-shader declarations and code for a frequency ("" if none needed).
std::string vertexDeclarations(const Variant& variant);
std::string vertexImplementation(Frequency frequency);

/// Fragment-shader declarations and the code that writes gl_FragData[0].
std::string fragmentDeclarations(const Variant& variant, bool tangentNormalMap);
std::string fragmentImplementation(Frequency frequency, const FragmentInputs& inputs);

} // namespace slLightingPassShaders

#endif
