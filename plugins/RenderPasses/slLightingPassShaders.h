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
  /// A .brdf file's BRDF (brdfSource()) shading in place of the model's
  /// diffuse and specular factors; empty: the model's.
  std::string brdf;
  /// Faces seen from behind take a material of their own, slMatBack (an
  /// actor's backface property): the lights then arrive without k_a, k_d,
  /// k_s, and each side's multiply the sums. Without one, nothing of this
  /// is in the shaders.
  bool backface = false;
  /// The actor's texture colours only faces seen from the front, as VTK
  /// draws a property with ShowTexturesOnBackfaceOff(). Only such actors
  /// get the side test (compiled in, where VTK tests a uniform); the
  /// others' shaders carry none of it.
  bool textureFrontOnly = false;
};

/// Whether @p fragmentShader (of a built program) is a Variant::backface
/// one, whose slMatBack and unfolded lights the pass has to set.
bool hasBackfaceMaterial(const std::string& fragmentShader);

/// The GLSL of a .brdf file's BRDF as the shaders hold it: its parameters'
/// uniform declarations followed, line for line, by its shader text.
/// @p uniformDeclarations is brdfUniformDeclarations() of the file.
std::string brdfSource(const std::string& uniformDeclarations, const std::string& shader);

/// The line (1-based) of @p source on which the .brdf shader text of
/// brdfSource() starts, for brdfCompileError(); 0 if @p source holds none.
int brdfShaderFirstLine(const std::string& source, int numberOfParameters);

/// A fragment shader of the variant's declarations alone whose main() calls
/// BRDF(): compiling it checks a .brdf file's GLSL before it goes into
/// VTK's shaders, whose compile errors come with the whole source.
std::string brdfCheckShader(const Variant& variant);

/// What the fragment shader has to work with, as found in VTK's shaders.
struct FragmentInputs
{
  bool scalarColors = false;    ///< diffuseColor carries point or cell scalars
  bool texture = false;         ///< actortexture and tcoordVCVSOutput exist
  bool mapperFaceNormal = false; ///< normalVCVSOutput is already per face (flat interpolation)
  bool tangentNormalMap = false; ///< normalTex + 4-component Tangents: ShadeLab maps the normal
  /// The mesh's 4-component Tangents reach the shaders as slTangentVC (for
  /// a normal map, an anisotropic model or a .brdf file's frame).
  bool surfaceTangent = false;
};

/// Vertex-shader declarations and code passing 4-component tangents
/// (xyz, handedness w) to the fragment shader as slTangentVC (per face,
/// from the provoking vertex, for @p frequency Flat).
std::string tangentVertexDeclarations(Frequency frequency);
std::string tangentVertexImplementation();

/// The GLSL expression of the lighting site's tangent (xyz, handedness w)
/// passed to slLightAll(): slTangentVC when the shaders carry the mesh's
/// 4-component Tangents, else vec4(0), which makes the BRDF frame one built
/// from the normal alone.
std::string tangentExpression(bool surfaceTangent);

/// Declarations for either stage: the lighting core, the uniforms, helpers,
/// for the variant's lights and model.
std::string declarations(const Variant& variant);

/// Vertex-shader declarations and code for the variant's frequency ("" if none needed).
std::string vertexDeclarations(const Variant& variant);
/// @p surfaceTangent: slTangentVC holds the mesh's tangents (Gouraud lights with them).
std::string vertexImplementation(const Variant& variant, bool surfaceTangent);

/// Fragment-shader declarations and the code that writes gl_FragData[0].
std::string fragmentDeclarations(const Variant& variant, const FragmentInputs& inputs);
std::string fragmentImplementation(const Variant& variant, const FragmentInputs& inputs);

/// The code that writes gl_FragData[0] where VTK does not light the
/// primitive (lines and points without point normals, or with flat
/// interpolation): VTK's unlit ambient + diffuse colour, times the actor's
/// texture when @p texture (on faces seen from the front only, for
/// @p textureFrontOnly: Variant::textureFrontOnly).
std::string unlitFragmentImplementation(bool texture, bool textureFrontOnly);

} // namespace slLightingPassShaders

#endif
