#ifndef shadelab_LightingGLSL_h
#define shadelab_LightingGLSL_h
/**
 * @file LightingGLSL.h
 * @brief The ShadeLab lighting equation compiled as C++: glsl/slLighting.glsl
 * included into namespace shadelab::glsl with GLM standing in for GLSL, and
 * after it glsl/slNormalMapping.glsl (slDecodeNormal, slTangentToSurface) and
 * glsl/slFalseColor.glsl (slRamp, slDiverging).
 *
 * This is how the CPU side evaluates the very same source text that the render
 * pass embeds into its shaders (see LightingShaderSource.h). Nothing here may
 * re-state a formula: add it to slLighting.glsl instead.
 *
 * Types: shadelab::glsl::slLight, slMaterial, slTerms; vec3 is glm::vec3.
 */

#include <glm/glm.hpp>

#include <cmath>

namespace shadelab
{
namespace glsl
{
using namespace glm;
#define SL_FUNC inline
#include "slLightingTables.glsl"
#include "slLighting.glsl"
#include "slNormalMapping.glsl"
#include "slFalseColor.glsl"
#undef SL_FUNC
} // namespace glsl
} // namespace shadelab

#endif
