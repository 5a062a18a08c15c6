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
 * inversesqrt is the hardware estimate plus a Newton step. pow is repeated
 * squaring when the exponent is the same whole number in every lane (a
 * material's shininess usually is; (n - 1) 2^-24 relative, see powWhole);
 * otherwise pow, exp2 and log2 are polynomial approximations without a
 * division (GLSL only asks for pow(x, y) = exp2(y log2 x) "to the precision
 * of" those two):
 * measured worst errors, in float arithmetic, are 2.2e-7 relative for exp2
 * and 1.5e-7 absolute for log2 of a positive normal float (plus the float
 * rounding of its result, 6e-8 |log2 x|), so pow's relative error is at most
 * about 2.2e-7 + ln 2 (1.5e-7 |y| + 1.2e-7 |y log2 x|): 1.2e-5 for a
 * shininess of 40 at x = 0.2. SIMDBatch tests these bounds against libm.
 * exp2 rounds with the 1.5 * 2^23 trick, so this file must not be compiled
 * with -ffast-math (which may fold (x + c) - c to x).
 * The exact libm versions are in shadelab::glsl (LightingGLSL.h).
 */

#ifdef __AVX__
#include <immintrin.h>
#endif

#ifdef __FAST_MATH__
#error "SIMDFloat8.h needs IEEE rounding (exp2 rounds with an added constant): compile without -ffast-math"
#endif

namespace shadelab
{
namespace simd
{

/// The raw vector types (GCC/Clang vector extensions).
typedef float v8sf __attribute__((vector_size(32)));
typedef int v8si __attribute__((vector_size(32)));
typedef unsigned v8su __attribute__((vector_size(32)));

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
inline vmask8 operator==(vfloat8 a, vfloat8 b) { return { a.v == b.v }; }
/// Lane-wise; both sides are evaluated (as for every select in the batch).
inline vmask8 operator&&(vmask8 a, vmask8 b) { return { a.m & b.m }; }
inline vmask8 operator||(vmask8 a, vmask8 b) { return { a.m | b.m }; }

/// Bit i set if lane i of @p c holds.
inline unsigned laneBits(vmask8 c)
{
#ifdef __AVX__
  return static_cast<unsigned>(_mm256_movemask_ps(reinterpret_cast<__m256>(c.m)));
#else
  unsigned bits = 0;
  for (int i = 0; i < 8; ++i)
  {
    bits |= (c.m[i] != 0 ? 1u : 0u) << i;
  }
  return bits;
#endif
}

/// GLSL any() and all(): the condition holds in some lane, in every lane.
inline bool any(vmask8 c) { return laneBits(c) != 0; }
inline bool all(vmask8 c) { return laneBits(c) == 0xffu; }

/// GLSL mix(a, b, bool c): per lane, c ? b : a.
inline vfloat8 mix(vfloat8 a, vfloat8 b, vmask8 c) { return vfloat8(c.m ? b.v : a.v); }

/// GLSL max and min: y if x < y (x > y), else x, as GLM computes them (x
/// where either is NaN). AVX's maxps(a, b) is a > b ? a : b: one instruction.
inline vfloat8 max(vfloat8 x, vfloat8 y)
{
#ifdef __AVX__
  return vfloat8(_mm256_max_ps(y.v, x.v));
#else
  return vfloat8(x.v < y.v ? y.v : x.v);
#endif
}
inline vfloat8 min(vfloat8 x, vfloat8 y)
{
#ifdef __AVX__
  return vfloat8(_mm256_min_ps(y.v, x.v));
#else
  return vfloat8(y.v < x.v ? y.v : x.v);
#endif
}
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

inline vfloat8 smoothstep(vfloat8 edge0, vfloat8 edge1, vfloat8 x)
{
  const vfloat8 t = clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

/// 2^x for x in [-126, 126] (clamped outside). Adding 1.5 * 2^23 + 127
/// rounds x to the nearest whole k and leaves k + 127, the biased exponent
/// of 2^k, in the low mantissa bits; 2^f for the rest f in [-0.5, 0.5] is a
/// degree-5 minimax polynomial (2.2e-7 relative).
inline vfloat8 exp2(vfloat8 x)
{
  x = clamp(x, -126.0f, 126.0f);
  const float roundAndBias = 12582912.0f + 127.0f; // exact: below 2^24
  const vfloat8 shifted = x + roundAndBias;
  const vfloat8 f = x - (shifted - roundAndBias);
  // Estrin's scheme: pairs first, so the chain of dependent operations is 3
  // multiply-adds long instead of Horner's 5 (measured faster in the
  // radiance loop, docs/lighting-cpu.md).
  const vfloat8 f2 = f * f;
  const vfloat8 p01 = 6.931469440460205e-1f * f + 1.0000001192092896f;
  const vfloat8 p23 = 5.550713464617729e-2f * f + 2.4022120237350464e-1f;
  const vfloat8 p45 = 1.3276452664285898e-3f * f + 9.675541892647743e-3f;
  const vfloat8 p = (p45 * f2 + p23) * f2 + p01;
  const v8su powerOfTwo = (v8su)shifted.v << 23; // a vector cast keeps the bits
  return p * vfloat8((v8sf)powerOfTwo);
}

/// log2(x) for finite x > 0: x = 2^e m with m in [sqrt(1/2), sqrt(2)),
/// found on the bits (subtracting the bits of sqrt(1/2) carries into the
/// exponent exactly when m would be below it), then log2(m) = t p(t) with
/// t = m - 1 and p a degree-7 minimax polynomial (1.5e-7 absolute). No
/// division. Other x give a finite but meaningless value (slPow selects
/// around them).
inline vfloat8 log2(vfloat8 x)
{
  // The bit arithmetic is unsigned (it wraps for negative x and -0, where
  // signed lanes would overflow); only the shift that extracts the signed
  // exponent works on signed lanes.
  const v8su bits = (v8su)x.v;
  const v8si e = (v8si)(bits - 0x3f3504f3u) >> 23;
  const vfloat8 t = vfloat8((v8sf)(bits - ((v8su)e << 23))) - 1.0f;
  // Estrin's scheme, as in exp2: 3 multiply-adds deep instead of 7.
  const vfloat8 t2 = t * t;
  const vfloat8 t4 = t2 * t2;
  const vfloat8 p01 = -0.7213525176048279f * t + 1.442694902420044f;
  const vfloat8 p23 = -0.3602634072303772f * t + 0.4809311628341675f;
  const vfloat8 p45 = -0.24832402169704437f * t + 0.28686925768852234f;
  const vfloat8 p67 = -0.1497257947921753f * t + 0.2357068955898285f;
  const vfloat8 p = (p67 * t2 + p45) * t4 + (p23 * t2 + p01);
  return t * p + vfloat8(__builtin_convertvector(e, v8sf));
}

/// The largest exponent pow() squares for. Its (n - 1) 2^-24 bound stays
/// below the polynomials' for every n; the cap is about cost: up to
/// 2 floor(log2 n) multiplications (18 for n = 1023) against about 25
/// operations for exp2(y log2 x).
constexpr unsigned maxWholeExponent = 1024;

/// x^n by repeated squaring: floor(log2 n) squarings and one multiplication
/// per further set bit of n (x^40: 6 instead of about 25 operations), 1 for
/// n = 0. Relative error at most (n - 1) 2^-24 to first order while x^n is
/// a normal float: the rounding of each square x^(2^k) is raised to the
/// power floor(n / 2^k) in the result (those powers add up to
/// n - popcount(n)), and the popcount(n) - 1 other products add one each.
/// Beyond the float range it overflows to infinity, or underflows gradually
/// through the subnormals to 0 (exp2 clamps instead).
inline vfloat8 powWhole(vfloat8 x, unsigned n)
{
  if (n == 0)
  {
    return vfloat8(1.0f);
  }
  vfloat8 square = x;
  for (; (n & 1u) == 0; n >>= 1)
  {
    square = square * square;
  }
  vfloat8 result = square;
  for (n >>= 1; n != 0; n >>= 1)
  {
    square = square * square;
    if (n & 1u)
    {
      result = result * square;
    }
  }
  return result;
}

/// The exponent n if every lane of y holds the same whole number in
/// [1, maxWholeExponent], else 0. A material's shininess is the same in
/// every lane, and usually whole.
inline unsigned uniformWholeExponent(vfloat8 y)
{
  const float first = y.v[0];
  if (!(first >= 1.0f && first <= float(maxWholeExponent)) || first != float(unsigned(first)))
  {
    return 0;
  }
  return all(y == first) ? unsigned(first) : 0u;
}

/// GLSL's definition: pow(x, y) = exp2(y log2 x), for x > 0; by repeated
/// squaring (more exact, and fewer operations) when y is the same whole
/// number in every lane.
inline vfloat8 pow(vfloat8 x, vfloat8 y)
{
  const unsigned n = uniformWholeExponent(y);
  return n != 0 ? powWhole(x, n) : exp2(y * log2(x));
}

} // namespace simd
} // namespace shadelab

#endif
