#ifndef shadelab_LightingGLSLBatch_h
#define shadelab_LightingGLSLBatch_h
/**
 * @file LightingGLSLBatch.h
 * @brief glsl/slLighting.glsl compiled as C++ a second time, into
 * shadelab::glsl8, with 8-lane SIMD batches standing in for GLSL's float and
 * vec3: every function shades 8 points at once.
 *
 * Same source text, same formulas. float is the batch type simd::vfloat8
 * (the file's float literals broadcast into it), vec3 is simd::vec3x8, bvec3
 * is simd::bvec3x8; int stays int, so the model and light-type branches stay
 * ordinary branches (give them constants and the compiler removes them). The
 * file makes every float-dependent choice with mix(a, b, condition), which
 * the batch types evaluate lane by lane. pow and exp2 are SIMDFloat8.h's
 * (repeated squaring for a whole shininess, polynomials otherwise); struct
 * fields are batches too (a light's values repeated in every lane). Use
 * shadelab::glsl (LightingGLSL.h, exact libm) unless 8 points are shaded
 * together; the CPU radiance filter's loop uses this and is tested against
 * shadelab::glsl.
 */

#include "shadelab/SIMDFloat8.h"
#include "shadelab/SIMDVec3x8.h"

namespace shadelab
{
namespace glsl8
{
using simd::vfloat8;
using vec3 = simd::vec3x8;
using bvec3 = simd::bvec3x8;

// GLSL's scalar type becomes the batch type for this one inclusion; every
// standard and GLM header is already included above, so nothing else sees it.
#define float vfloat8
#define SL_FUNC inline
#include "slLightingTables.glsl"
#include "slLighting.glsl"
#undef SL_FUNC
#undef float
} // namespace glsl8
} // namespace shadelab

#endif
