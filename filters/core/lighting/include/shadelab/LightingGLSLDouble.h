#ifndef shadelab_LightingGLSLDouble_h
#define shadelab_LightingGLSLDouble_h
/**
 * @file LightingGLSLDouble.h
 * @brief glsl/slLighting.glsl (and glsl/slNormalMapping.glsl after it)
 * compiled as C++ once more, into shadelab::glsld, with double standing in
 * for GLSL's float and glm::dvec3 for vec3: the same formulas evaluated in
 * double precision.
 *
 * For integrals that need more than float's 7 digits, such as the directional
 * albedo at shininess 10^4, where x^n of a cosine rounded to float is off by
 * n times float's rounding (Albedo.h), and for the CPU normal-map filters,
 * which work in double. The files' float literals stay float
 * and are widened where they meet a double; the overloads below give the
 * GLSL built-ins those mixed calls (GLM's templates want one type).
 */

#include <glm/glm.hpp>

#include <cmath>

namespace shadelab
{
namespace glsld
{
using namespace glm;
using vec3 = glm::dvec3;
using bvec3 = glm::bvec3;

inline double max(double a, double b)
{
  return a < b ? b : a;
}
inline double min(double a, double b)
{
  return b < a ? b : a;
}
inline double clamp(double x, double low, double high)
{
  return min(max(x, low), high);
}
inline double mix(double a, double b, bool select)
{
  return select ? b : a;
}

// GLSL's scalar type becomes double for this one inclusion; every standard
// and GLM header is already included above, so nothing else sees it.
#define float double
#define SL_FUNC inline
#include "slLightingTables.glsl"
#include "slLighting.glsl"
#include "slNormalMapping.glsl"
#undef SL_FUNC
#undef float
} // namespace glsld
} // namespace shadelab

#endif
