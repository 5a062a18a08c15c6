#include "slLightingPassShaders.h"

#include "shadelab/LightingShaderSource.h"

#include <algorithm>

namespace slLightingPassShaders
{

namespace
{
/// GLSL returning the compiled-in type of light i: after the constant-bound
/// loop unrolls, every test of a light's type folds away.
std::string lightTypeFunction(const std::vector<int>& types)
{
  std::string body = "0";
  for (size_t i = types.size(); i-- > 0;)
  {
    body = "i == " + std::to_string(i) + " ? " + std::to_string(types[i]) + " : (" + body + ")";
  }
  return "int slLightTypeOf(int i)\n{\n  return " + body + ";\n}\n";
}

const char* const kBrdfMarker = "// ---- BRDF of a .brdf file: its parameters, then its shader ----\n";

const char* const kBackfaceDeclaration =
  "uniform slMaterial slMatBack; // faces seen from behind: the actor's backface property\n";

/// The GLSL material of the side a fragment shows: slMatBack for faces seen
/// from behind in a Variant::backface variant, else slMat.
std::string sideMaterial(const Variant& variant)
{
  return variant.backface ? "(gl_FrontFacing == false ? slMatBack : slMat)" : "slMat";
}

/// The GLSL line that runs @p statement (which multiplies the actor's
/// texture in) on every face, or only on faces seen from the front for
/// @p frontOnly (Variant::textureFrontOnly). VTK 9.1 tests
/// "gl_FrontFacing == true || showTexturesOnBackface" in every textured
/// shader; here the test is in only the shaders of actors that need it.
std::string textureLine(const std::string& indent, const std::string& statement, bool frontOnly)
{
  return indent + (frontOnly ? "if (gl_FrontFacing == true) { " + statement + " } // ShowTexturesOnBackfaceOff"
                             : statement) + "\n";
}

/// GLSL of one light shaded with a .brdf file's BRDF.
std::string brdfFunctions()
{
  return "// One light shaded with the file's BRDF at unit normal n with frame X, Y:\n"
         "// the lighting core weighs the light as for the Lambert model, whose\n"
         "// diffuse weight is the light's reach (attenuation, spot factor) times\n"
         "// max(N.L, 0) and whose ambient weight is every model's; the BRDF then\n"
         "// multiplies the diffuse term in place of k_d (the light arrives folded\n"
         "// with k_d = 1). Where N.L <= 0 the BRDF is not called: it may divide by N.L.\n"
         "slTerms slShadeBrdf(slLight light, slMaterial unit, vec3 P, vec3 n, vec3 v, vec3 X, vec3 Y)\n"
         "{\n"
         "  slTerms t = slWeightedTerms(slLightWeightsAt(light, unit, SL_MODEL_LAMBERT, P, n, X, v), light, unit);\n"
         "  vec3 L = slIncidenceAt(light, P).L;\n"
         "  if (light.type != SL_LIGHT_AMBIENT && dot(n, L) > 0.0f)\n"
         "  {\n"
         "    t.diffuse = t.diffuse * BRDF(L, v, n, X, Y);\n"
         "  }\n"
         "  return t;\n"
         "}\n";
}
} // namespace

bool hasBackfaceMaterial(const std::string& fragmentShader)
{
  return fragmentShader.find(kBackfaceDeclaration) != std::string::npos;
}

std::string tangentExpression(bool surfaceTangent)
{
  return surfaceTangent ? "slTangentVC" : "vec4(0.0f)";
}

std::string brdfSource(const std::string& uniformDeclarations, const std::string& shader)
{
  std::string text = kBrdfMarker + uniformDeclarations + shader;
  if (!text.empty() && text.back() != '\n')
  {
    text += '\n';
  }
  return text;
}

int brdfShaderFirstLine(const std::string& source, int numberOfParameters)
{
  const size_t at = source.find(kBrdfMarker);
  if (at == std::string::npos)
  {
    return 0;
  }
  const auto linesBefore = std::count(source.begin(), source.begin() + static_cast<std::ptrdiff_t>(at), '\n');
  // The marker's line, then one uniform line per parameter.
  return static_cast<int>(linesBefore) + 2 + numberOfParameters;
}

std::string declarations(const Variant& variant)
{
  const std::vector<int>& lightTypes = variant.lightTypes;
  const bool brdf = !variant.brdf.empty();
  return "// ---- ShadeLab lighting (slLighting.glsl, the lighting core's single copy) ----\n" +
    shadelab::lightingShaderSource() + variant.brdf + (brdf ? brdfFunctions() : std::string()) +
    "// ---- ShadeLab lighting pass ----\n"
    "const int SL_MAX_LIGHTS = " +
    std::to_string(MaximumLights) +
    ";\n"
    "uniform slLight slLights[SL_MAX_LIGHTS];\n"
    "// The light count and types are compiled in: the loop unrolls and type tests fold.\n"
    "const int slLightCount = " +
    std::to_string(lightTypes.size()) + ";\n" + lightTypeFunction(lightTypes) +
    "uniform slMaterial slMat;\n" +
    std::string(variant.backface ? kBackfaceDeclaration : "") +
    "const int slModel = " + std::to_string(variant.model) + "; // compiled in: model tests fold\n"
    "// Compiled in: without a component view the shaders hold no code for one\n"
    "// (llvmpipe runs both sides of every branch, taken or not).\n"
    "const bool slComponentView = " +
    std::string(variant.componentView ? "true" : "false") +
    ";\n"
    "uniform int slComponent;       // 0 total, 1 ambient, 2 diffuse, 3 specular, 4 emission, 5 cos theta\n"
    "uniform int slComponentLight;  // -1: all lights, else only this one\n"
    "uniform int slFalseColor;\n"
    "uniform int slParallel;\n"
    "\n"
    "// The eye for a view-coordinate point: the origin, or straight back for parallel projection.\n"
    "vec3 slEye(vec3 P)\n"
    "{\n"
    "  return slParallel == 1 ? P + vec3(0.0f, 0.0f, 1.0f) : vec3(0.0f);\n"
    "}\n"
    "\n"
    "// All lights (or the chosen one) at P with normal N and tangent T (xyz,\n"
    "// MikkTSpace handedness w; 0 without one) on a side of material m (slMat,\n"
    "// or slMatBack seen from behind). " +
    std::string(variant.backface
        ? "The lights arrive without k_a, k_d, k_s, which differ\n"
          "// by side: m's multiply the sums here. "
        : "The lights arrive with k_a, k_d, k_s\n"
          "// folded in (slFoldLight). ") +
    "The base colour (scalars, texture)\n"
    "// multiplies the sum afterwards (slWithBaseColour).\n"
    "slTerms slLightAll(vec3 P, vec3 N, vec4 T, slMaterial m)\n"
    "{\n"
    "  slMaterial unit = slUnitMaterial(m);\n"
    "  vec3 n = slSafeNormalize(N);\n"
    "  vec3 v = slSafeNormalize(slEye(P) - P);\n" +
    std::string(brdf ? "  // The .brdf frame: the lighting core's tangent X (the frame built from\n"
                       "  // n where T gives none) and Y = w (n x X).\n"
                       "  vec3 X = slTangentX(n, T.xyz);\n"
                       "  vec3 Y = (T.w < 0.0f ? -1.0f : 1.0f) * slBitangentY(n, X);\n"
                     : "") +
    "  slTerms t = slZeroTerms();\n"
    "  for (int i = 0; i < slLightCount; ++i)\n"
    "  {\n"
    "    if (!slComponentView || slComponentLight < 0 || i == slComponentLight)\n"
    "    {\n"
    "      slLight light = slLights[i];\n"
    "      light.type = slLightTypeOf(i);\n" +
    std::string(brdf ? "      t = slAddTerms(t, slShadeBrdf(light, unit, P, n, v, X, Y));\n"
                     : "      t = slAddTerms(t, slShadeLightUnit(light, unit, slModel, P, n, T.xyz, v));\n") +
    "    }\n"
    "  }\n" +
    std::string(variant.backface ? "  t.ambient = t.ambient * m.ambient;\n"
                                   "  t.diffuse = t.diffuse * m.diffuse;\n"
                                   "  t.specular = t.specular * m.specular;\n"
                                 : "") +
    "  return t;\n"
    "}\n"
    "\n"
    "// Raw N.L (slCosTheta of the lighting core) of the chosen light, light 0\n"
    "// when all are chosen; negative: the surface shadows itself.\n"
    "float slChosenCosTheta(vec3 P, vec3 N)\n"
    "{\n"
    "  int k = max(slComponentLight, 0);\n"
    "  if (k >= slLightCount) { return 0.0f; }\n"
    "  slLight light = slLights[k];\n"
    "  light.type = slLightTypeOf(k);\n"
    "  return slCosTheta(light, P, N);\n"
    "}\n";
}

std::string brdfCheckShader(const Variant& variant)
{
  return "#version 150\n" + declarations(variant) +
    "out vec4 slCheckOutput;\n"
    "void main()\n"
    "{\n"
    "  slCheckOutput = vec4(slLightAll(vec3(0.0f), vec3(0.0f, 0.0f, 1.0f), vec4(0.0f), slMat).diffuse, 1.0f);\n"
    "}\n";
}

std::string vertexDeclarations(const Variant& variant)
{
  switch (variant.frequency)
  {
    case Flat:
      return "flat out vec4 slFlatVertexVC;\n";
    case Gouraud:
      return declarations(variant) +
        "out vec3 slAmbientVS;\nout vec3 slDiffuseVS;\nout vec3 slSpecularVS;\nout float slCosThetaVS;\n"
        "out vec3 slAmbientBackVS;\nout vec3 slDiffuseBackVS;\nout vec3 slSpecularBackVS;\n";
    case Phong:
      break;
  }
  return std::string();
}

std::string vertexImplementation(const Variant& variant, bool surfaceTangent)
{
  const std::string T = tangentExpression(surfaceTangent);
  switch (variant.frequency)
  {
    case Flat:
      return "  slFlatVertexVC = vertexVCVSOutput; // the provoking vertex lights the whole face\n";
    case Gouraud:
      // True Gouraud: light once per vertex, for the front and the back side
      // (the flipped normal, and the backface material if there is one).
      return "  {\n"
             "    vec3 slP = vertexVCVSOutput.xyz;\n"
             "    vec3 slN = normalVCVSOutput;\n"
             "    slTerms slFront = slLightAll(slP, slN, " + T + ", slMat);\n"
             "    slTerms slBack = slLightAll(slP, -slN, " + T + ", " + (variant.backface ? "slMatBack" : "slMat") + ");\n"
             "    slAmbientVS = slFront.ambient;\n"
             "    slDiffuseVS = slFront.diffuse;\n"
             "    slSpecularVS = slFront.specular;\n"
             "    slAmbientBackVS = slBack.ambient;\n"
             "    slDiffuseBackVS = slBack.diffuse;\n"
             "    slSpecularBackVS = slBack.specular;\n"
             "    slCosThetaVS = slComponentView && slComponent == 5 ? slChosenCosTheta(slP, slN) : 0.0f;\n"
             "  }\n";
    case Phong:
      break;
  }
  return std::string();
}

std::string tangentVertexDeclarations(Frequency frequency)
{
  // Flat: the provoking vertex's tangent, as its position, lights the face.
  return std::string("in vec4 slTangentMC;\n") + (frequency == Flat ? "flat " : "") + "out vec4 slTangentVC;\n";
}

std::string tangentVertexImplementation()
{
  // A tangent lies in the surface: it goes to view coordinates as a
  // direction (the model-view matrix; normals take its inverse transpose).
  // MCVCMatrix is in every lit vertex shader, normalMatrix not in flat ones.
  return "  slTangentVC = vec4(mat3(MCVCMatrix) * slTangentMC.xyz, slTangentMC.w);\n";
}

std::string fragmentDeclarations(const Variant& variant, const FragmentInputs& inputs)
{
  const Frequency frequency = variant.frequency;
  std::string out = declarations(variant);
  if (inputs.surfaceTangent && frequency != Gouraud)
  {
    out += std::string(frequency == Flat ? "flat " : "") + "in vec4 slTangentVC;\n";
  }
  if (inputs.tangentNormalMap)
  {
    out += shadelab::normalMappingShaderSource();
    out += "uniform float slNormalScale;\n";
  }
  if (frequency == Flat)
  {
    out += "flat in vec4 slFlatVertexVC;\n";
  }
  if (frequency == Gouraud)
  {
    out += "in vec3 slAmbientVS;\nin vec3 slDiffuseVS;\nin vec3 slSpecularVS;\nin float slCosThetaVS;\n"
           "in vec3 slAmbientBackVS;\nin vec3 slDiffuseBackVS;\nin vec3 slSpecularBackVS;\n";
  }
  out += shadelab::falseColorShaderSource();
  out += "\n"
         "vec3 slShowScalar(float s)\n"
         "{\n"
         "  return slFalseColor == 1 ? slRamp(s) : vec3(clamp(s, 0.0f, 1.0f));\n"
         "}\n"
         "\n"
         "// The picture: the total, or one component for teaching and debugging.\n"
         "vec3 slCompose(slTerms t, float cosTheta, vec3 base)\n"
         "{\n"
         "  slTerms coloured = slWithBaseColour(t, base);\n"
         "  vec3 ambient = coloured.ambient;\n"
         "  vec3 diffuse = coloured.diffuse;\n"
         "  vec3 specular = coloured.specular;\n"
         "  vec3 emission = slMat.emission; // one for both sides: a vtkProperty has none\n"
         "  if (!slComponentView) { return ambient + diffuse + specular + emission; }\n"
         "  if (slComponent == 1) { return slFalseColor == 1 ? slRamp(slLuminance(ambient)) : ambient; }\n"
         "  if (slComponent == 2) { return slFalseColor == 1 ? slRamp(slLuminance(diffuse)) : diffuse; }\n"
         "  if (slComponent == 3) { return slFalseColor == 1 ? slRamp(slLuminance(specular)) : specular; }\n"
         "  if (slComponent == 4) { return slFalseColor == 1 ? slRamp(slLuminance(emission)) : emission; }\n"
         "  if (slComponent == 5) { return slFalseColor == 1 ? slDiverging(cosTheta) : slShowScalar(cosTheta); }\n"
         "  return ambient + diffuse + specular + emission;\n"
         "}\n";
  return out;
}

std::string unlitFragmentImplementation(bool texture, bool textureFrontOnly)
{
  // VTK's own unlit colour (vtkOpenGLPolyDataMapper, no light complexity),
  // then the actor's texture, which VTK multiplies into the whole colour.
  return std::string("  gl_FragData[0] = vec4(ambientColor + diffuseColor, opacity);\n") +
    (texture ? textureLine("  ", "gl_FragData[0] = gl_FragData[0] * texture(actortexture, tcoordVCVSOutput);",
                 textureFrontOnly)
             : "");
}

std::string fragmentImplementation(const Variant& variant, const FragmentInputs& inputs)
{
  // The normals here already face the eye on faces seen from behind (VTK
  // flips its own, the flat one is turned toward the eye).
  const std::string tangentAndMaterial = tangentExpression(inputs.surfaceTangent) + ", " + sideMaterial(variant);
  std::string out = "  {\n    vec3 slBase = vec3(1.0f);\n";
  if (inputs.scalarColors)
  {
    // VTK writes the scalar colour times each intensity into both colours;
    // either gives it back (a property with k_d = 0 still shows its scalars
    // in the ambient term).
    out += "    slBase = diffuseIntensity > 0.0f ? diffuseColor / diffuseIntensity\n"
           "           : (ambientIntensity > 0.0f ? ambientColor / ambientIntensity : vec3(1.0f));\n";
  }
  if (inputs.texture)
  {
    out += textureLine(
      "    ", "slBase = slBase * texture(actortexture, tcoordVCVSOutput).rgb;", variant.textureFrontOnly);
  }
  out += "    slTerms slT;\n    float slCos;\n";
  switch (variant.frequency)
  {
    case Flat:
      if (inputs.mapperFaceNormal)
      {
        out += "    vec3 slN = normalVCVSOutput; // cell normals, or VTK's own face normal\n";
      }
      else
      {
        out += "    vec3 slN = cross(dFdx(vertexVC.xyz), dFdy(vertexVC.xyz));\n"
               "    if (dot(slN, slEye(vertexVC.xyz) - vertexVC.xyz) < 0.0f) { slN = -slN; }\n";
      }
      out += "    slT = slLightAll(slFlatVertexVC.xyz, slN, " + tangentAndMaterial + ");\n"
             "    slCos = slComponentView && slComponent == 5 ? slChosenCosTheta(slFlatVertexVC.xyz, slN) : 0.0f;\n";
      break;
    case Gouraud:
      out += "    slT = slZeroTerms();\n"
             "    slT.ambient = gl_FrontFacing ? slAmbientVS : slAmbientBackVS;\n"
             "    slT.diffuse = gl_FrontFacing ? slDiffuseVS : slDiffuseBackVS;\n"
             "    slT.specular = gl_FrontFacing ? slSpecularVS : slSpecularBackVS;\n"
             "    slCos = gl_FrontFacing ? slCosThetaVS : -slCosThetaVS;\n";
      break;
    case Phong:
      if (inputs.tangentNormalMap)
      {
        // Tangent-space normal map (OpenGL, green up) with MikkTSpace
        // handedness, decoded as the CPU's slNormalMapFilter does.
        out += "    normalVCVSOutput = slTangentToSurface(slDecodeNormal(texture(normalTex, tcoordVCVSOutput).rgb, 1.0f,"
               " slNormalScale), normalVCVSOutput, slTangentVC.xyz, slTangentVC.w);\n";
      }
      out += "    slT = slLightAll(vertexVC.xyz, normalVCVSOutput, " + tangentAndMaterial + ");\n"
             "    slCos = slComponentView && slComponent == 5 ? slChosenCosTheta(vertexVC.xyz, normalVCVSOutput) : 0.0f;\n";
      break;
  }
  out += "    gl_FragData[0] = vec4(slCompose(slT, slCos, slBase), opacity);\n  }\n";
  return out;
}

} // namespace slLightingPassShaders
