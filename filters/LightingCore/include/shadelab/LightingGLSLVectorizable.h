#ifndef shadelab_LightingGLSLVectorizable_h
#define shadelab_LightingGLSLVectorizable_h
/**
 * @file LightingGLSLVectorizable.h
 * @brief glsl/slLighting.glsl compiled as C++ a second time, into
 * shadelab::glslv, with the two transcendental built-ins it uses (pow, exp2)
 * replaced by inline polynomial versions that a compiler can vectorise.
 *
 * Same source text, same formulas: only the built-ins differ. GLSL itself
 * defines pow(x, y) as exp2(y * log2(x)) with the precision of those two,
 * and that is what glslv::pow computes (relative error about 1e-6 per unit of
 * |y log2 x|). libm's powf and exp2f are opaque calls that stop GCC from
 * vectorising a loop over points; these are not. Use shadelab::glsl (exact
 * libm built-ins) unless a loop must vectorise; the CPU radiance filter's
 * fast path uses this and is tested against shadelab::glsl.
 */

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>

namespace shadelab
{
namespace glslv
{
using namespace glm;

/// 2^x for x in [-126, 126] (clamped outside): Taylor-like minimax
/// polynomial of degree 6 on the fraction, exponent put into the float's bits.
inline float exp2(float x)
{
  x = x < -126.0f ? -126.0f : (x > 126.0f ? 126.0f : x);
  const float whole = std::floor(x);
  const float f = x - whole;
  float p = 1.535336188319500e-4f;
  p = p * f + 1.339887440266574e-3f;
  p = p * f + 9.618437357674640e-3f;
  p = p * f + 5.550332471162809e-2f;
  p = p * f + 2.402264791363012e-1f;
  p = p * f + 6.931472028550421e-1f;
  p = p * f + 1.0f;
  const std::int32_t bits = (static_cast<std::int32_t>(whole) + 127) << 23;
  float scale;
  std::memcpy(&scale, &bits, sizeof scale);
  return p * scale;
}

/// log2(x) for finite x > 0: exponent from the bits, mantissa m in [1, 2)
/// through the atanh series of log2(m) = 2/ln2 atanh((m-1)/(m+1)).
inline float log2(float x)
{
  std::int32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const float exponent = static_cast<float>(((bits >> 23) & 255) - 127);
  bits = (bits & 0x007fffff) | 0x3f800000;
  float m;
  std::memcpy(&m, &bits, sizeof m);
  const float t = (m - 1.0f) / (m + 1.0f);
  const float t2 = t * t;
  const float series = t *
    (2.885390081777927f +
      t2 * (0.961796693925976f + t2 * (0.577078016355585f + t2 * (0.412198585348200f + t2 * 0.320903869185000f))));
  return exponent + series;
}

/// GLSL's definition: pow(x, y) = exp2(y log2 x) for x > 0 (slPow guards x <= 0).
inline float pow(float x, float y)
{
  return exp2(y * log2(x));
}

#define SL_FUNC inline
#include "slLighting.glsl"
#undef SL_FUNC
} // namespace glslv
} // namespace shadelab

#endif
