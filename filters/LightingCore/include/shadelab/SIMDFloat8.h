#ifndef shadelab_SIMDFloat8_h
#define shadelab_SIMDFloat8_h
/**
 * @file SIMDFloat8.h
 * @brief vfloat8 and vmask8: 8 floats (and 8 lane conditions) that behave
 * like GLSL's float (and bool) under the operators and built-ins that
 * slLighting.glsl uses, so that the file compiles for 8 points at a time
 * (see LightingGLSLBatch.h).
 *
 * Written with GCC's generic vector extensions, so any target compiles them
 * (AVX/AVX2 + FMA: one instruction per operation; SSE: two). Comparisons
 * give a vmask8 (a lane is all ones or all zeros); mix(a, b, mask) selects
 * per lane, which is how slLighting.glsl writes every float-dependent
 * choice. Nothing here knows about lighting.
 *
 * inversesqrt is the hardware estimate plus a Newton step; pow, exp2 and
 * log2 are polynomial approximations (GLSL only asks for
 * pow(x, y) = exp2(y log2 x) "to the precision of" those two): measured
 * worst errors are 5.6e-6 relative for exp2 on [-100, 100] and 2e-6
 * absolute for log2 of a positive normal float, so pow's relative error is
 * at most about 5.6e-6 + 1.4e-6 |y| (6e-5 for a shininess of 40).
 * The exact libm versions are in shadelab::glsl (LightingGLSL.h).
 */

#ifdef __AVX__
#include <immintrin.h>
#endif

namespace shadelab
{
namespace simd
{

/// The raw vector types (GCC/Clang vector extensions).
typedef float v8sf __attribute__((vector_size(32)));
typedef int v8si __attribute__((vector_size(32)));

/// 8 lane conditions: each lane is -1 (true) or 0 (false).
struct vmask8
{
  v8si m;
};

/// 8 floats, one per point of a batch; a float converts by broadcasting.
struct vfloat8
{
  v8sf v;
  vfloat8() = default;
  constexpr vfloat8(float s) // NOLINT: implicit, as GLSL literals mix with floats
    : v{ s, s, s, s, s, s, s, s }
  {
  }
  constexpr explicit vfloat8(v8sf x)
    : v(x)
  {
  }
};

inline vfloat8 operator+(vfloat8 a, vfloat8 b) { return vfloat8(a.v + b.v); }
inline vfloat8 operator-(vfloat8 a, vfloat8 b) { return vfloat8(a.v - b.v); }
inline vfloat8 operator*(vfloat8 a, vfloat8 b) { return vfloat8(a.v * b.v); }
inline vfloat8 operator/(vfloat8 a, vfloat8 b) { return vfloat8(a.v / b.v); }
inline vfloat8 operator-(vfloat8 a) { return vfloat8(-a.v); }

inline vmask8 operator<(vfloat8 a, vfloat8 b) { return { a.v < b.v }; }
inline vmask8 operator>(vfloat8 a, vfloat8 b) { return { a.v > b.v }; }
inline vmask8 operator<=(vfloat8 a, vfloat8 b) { return { a.v <= b.v }; }
inline vmask8 operator>=(vfloat8 a, vfloat8 b) { return { a.v >= b.v }; }
/// Lane-wise; both sides are evaluated (as for every select in the batch).
inline vmask8 operator&&(vmask8 a, vmask8 b) { return { a.m & b.m }; }
inline vmask8 operator||(vmask8 a, vmask8 b) { return { a.m | b.m }; }

/// GLSL mix(a, b, bool c): per lane, c ? b : a.
inline vfloat8 mix(vfloat8 a, vfloat8 b, vmask8 c) { return vfloat8(c.m ? b.v : a.v); }

/// GLSL max and min: y if x < y (x > y), else x, as GLM computes them.
inline vfloat8 max(vfloat8 x, vfloat8 y) { return vfloat8(x.v < y.v ? y.v : x.v); }
inline vfloat8 min(vfloat8 x, vfloat8 y) { return vfloat8(y.v < x.v ? y.v : x.v); }
inline vfloat8 clamp(vfloat8 x, vfloat8 lo, vfloat8 hi) { return min(max(x, lo), hi); }

inline vfloat8 sqrt(vfloat8 x)
{
#ifdef __AVX__
  return vfloat8(_mm256_sqrt_ps(x.v));
#else
  v8sf r;
  for (int i = 0; i < 8; ++i)
  {
    r[i] = __builtin_sqrtf(x.v[i]);
  }
  return vfloat8(r);
#endif
}

/// GLSL inversesqrt, 1 / sqrt(x), without a square root or a division: the
/// hardware's 12-bit estimate refined by one Newton step, to about 3e-7
/// relative for normal positive x (SIMDBatch tests it against libm). For 0,
/// subnormal, infinite or NaN x the result is NaN or infinite; slLighting.glsl
/// selects around those (slScaleToUnit).
inline vfloat8 inversesqrt(vfloat8 x)
{
#ifdef __AVX__
  const v8sf estimate = _mm256_rsqrt_ps(x.v);
  return vfloat8(estimate * (1.5f - (0.5f * x.v) * estimate * estimate));
#else
  return vfloat8(1.0f / sqrt(x).v);
#endif
}

/// floor through truncation toward zero, one down where that went up.
inline vfloat8 floor(vfloat8 x)
{
  const v8sf t = __builtin_convertvector(__builtin_convertvector(x.v, v8si), v8sf);
  return vfloat8(t > x.v ? t - 1.0f : t);
}

inline vfloat8 smoothstep(vfloat8 edge0, vfloat8 edge1, vfloat8 x)
{
  const vfloat8 t = clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

/// 2^x for x in [-126, 126] (clamped outside): minimax polynomial of degree 6
/// on the fraction, the whole part put into the float's exponent bits.
inline vfloat8 exp2(vfloat8 x)
{
  x = clamp(x, -126.0f, 126.0f);
  const vfloat8 whole = floor(x);
  const vfloat8 f = x - whole;
  vfloat8 p = 1.535336188319500e-4f;
  p = p * f + 1.339887440266574e-3f;
  p = p * f + 9.618437357674640e-3f;
  p = p * f + 5.550332471162809e-2f;
  p = p * f + 2.402264791363012e-1f;
  p = p * f + 6.931472028550421e-1f;
  p = p * f + 1.0f;
  const v8si bits = (__builtin_convertvector(whole.v, v8si) + 127) << 23;
  return p * vfloat8((v8sf)bits); // a vector cast keeps the bits
}

/// log2(x) for finite x > 0: exponent from the bits, mantissa m in [1, 2)
/// through the atanh series log2(m) = 2/ln2 atanh((m-1)/(m+1)). Other x give
/// a finite but meaningless value (slPow selects around them).
inline vfloat8 log2(vfloat8 x)
{
  const v8si bits = (v8si)x.v;
  const vfloat8 exponent(__builtin_convertvector(((bits >> 23) & 255) - 127, v8sf));
  const v8si mantissaBits = (bits & 0x007fffff) | 0x3f800000;
  const vfloat8 m((v8sf)mantissaBits);
  const vfloat8 t = (m - 1.0f) / (m + 1.0f);
  const vfloat8 t2 = t * t;
  const vfloat8 series = t *
    (2.885390081777927f +
      t2 * (0.961796693925976f + t2 * (0.577078016355585f + t2 * (0.412198585348200f + t2 * 0.320903869185000f))));
  return exponent + series;
}

/// GLSL's definition: pow(x, y) = exp2(y log2 x), for x > 0.
inline vfloat8 pow(vfloat8 x, vfloat8 y)
{
  return exp2(y * log2(x));
}

} // namespace simd
} // namespace shadelab

#endif
