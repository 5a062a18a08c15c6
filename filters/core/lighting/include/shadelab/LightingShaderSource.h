#ifndef shadelab_LightingShaderSource_h
#define shadelab_LightingShaderSource_h
/**
 * @file LightingShaderSource.h
 * @brief The text of glsl/slLighting.glsl (and of slNormalMapping.glsl and
 * slFalseColor.glsl), embedded at build time, ready to be spliced into a
 * GLSL 1.50 shader.
 *
 * The build generates the definition from the .glsl file itself, so the GPU
 * and the CPU (LightingGLSL.h) always compile the same characters.
 */

#include <string>

namespace shadelab
{
/// The lighting functions as GLSL, prefixed with `#define SL_FUNC` so that the
/// file's function markers vanish, then the generated constants
/// (lightingTablesShaderSource()), then slLighting.glsl. Insert after the
/// `#version` line.
const std::string& lightingShaderSource();
/// slLightingTables.glsl: the SL_MODEL_* and SL_LIGHT_* constants and
/// slIsNormalizedModel(), generated at build time from LightingTables.h.
const std::string& lightingTablesShaderSource();
/// glsl/slNormalMapping.glsl; insert after lightingShaderSource().
const std::string& normalMappingShaderSource();
/// glsl/slFalseColor.glsl; insert after lightingShaderSource().
const std::string& falseColorShaderSource();
} // namespace shadelab

#endif
