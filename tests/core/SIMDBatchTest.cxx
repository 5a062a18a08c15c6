// The 8-lane batch types (SIMDFloat8.h, SIMDVec3x8.h) that compile
// slLighting.glsl for the radiance filter's loop: their built-ins against
// <cmath>, and lane independence of the mix() selects.
#include "shadelab/LightingGLSL.h"
#include "shadelab/LightingGLSLBatch.h"
#include "shadelab/LightingGLSLDouble.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

using shadelab::simd::vfloat8;

namespace
{
vfloat8 lanes(const float (&v)[8])
{
  vfloat8 r;
  for (int i = 0; i < 8; ++i)
  {
    r.v[i] = v[i];
  }
  return r;
}
} // namespace

TEST(SIMDBatch, Exp2Log2AndPowAgreeWithLibm)
{
  // Polynomial built-ins (see SIMDFloat8.h): exp2 to 2.2e-7 relative; log2 to
  // 1.5e-7 absolute plus the float rounding of the result (6e-8 |log2 x|); so
  // pow(x, y) = exp2(y log2 x) to 2.2e-7 + ln 2 (1.5e-7 |y| + 1.2e-7 |y log2 x|)
  // relative (log2's rounding and that of the product y log2 x). Checked with
  // a 1.5x margin, against libm in double.
  std::mt19937 random(7);
  std::uniform_real_distribution<float> exponent(-100.0f, 100.0f), base(1e-6f, 1.0f), shininess(0.0f, 200.0f);
  for (int round = 0; round < 2000; ++round)
  {
    float x[8], y[8], e[8];
    for (int i = 0; i < 8; ++i)
    {
      e[i] = exponent(random);
      x[i] = base(random) * (i % 2 ? 1000.0f : 1.0f);
      y[i] = shininess(random);
    }
    const vfloat8 ex = shadelab::simd::exp2(lanes(e)), lx = shadelab::simd::log2(lanes(x)),
                  px = shadelab::simd::pow(lanes(x), lanes(y));
    for (int i = 0; i < 8; ++i)
    {
      EXPECT_NEAR(ex.v[i] / std::exp2(double(e[i])), 1.0, 1.5 * 2.2e-7) << e[i];
      const double log2x = std::log2(double(x[i]));
      EXPECT_NEAR(lx.v[i], log2x, 1.5 * (1.5e-7 + 6e-8 * std::abs(log2x))) << x[i];
      const double exact = std::pow(double(x[i]), double(y[i]));
      const double bound = 1.5 * (2.2e-7 + 0.6931 * (1.5e-7 * y[i] + 1.2e-7 * std::abs(y[i] * log2x)));
      if (exact > 1e-30 && exact < 1e30) // exp2's clamp to [-126, 126] aside
      {
        EXPECT_NEAR(px.v[i] / exact, 1.0, bound) << x[i] << "^" << y[i];
      }
    }
  }
}

TEST(SIMDBatch, PowByRepeatedSquaringForAUniformWholeExponent)
{
  // A shininess that is the same whole n in every lane takes powWhole: at most
  // (n - 1) 2^-24 relative to first order (see powWhole), tighter than the
  // polynomial path's bound (1.2e-5 for x = 0.2, n = 40), so this also fails
  // if the polynomial path were taken. Every n from 1 to 1024, against libm
  // in double, with 1% margin (the second-order terms), over the normal
  // float range of x^n.
  namespace simd = shadelab::simd;
  std::mt19937 random(13);
  std::uniform_real_distribution<float> base(0.0f, 1.0f);
  for (unsigned n = 1; n <= simd::maxWholeExponent; ++n)
  {
    ASSERT_EQ(simd::uniformWholeExponent(vfloat8(float(n))), n);
    for (int round = 0; round < 8; ++round)
    {
      float x[8];
      for (int i = 0; i < 8; ++i)
      {
        x[i] = base(random) * (i == 0 ? 1.05f : 1.0f); // a cosine may round above 1
      }
      const vfloat8 p = simd::pow(lanes(x), vfloat8(float(n)));
      for (int i = 0; i < 8; ++i)
      {
        const double exact = std::pow(double(x[i]), double(n));
        if (exact > 1.2e-38 && exact < 3e38)
        {
          EXPECT_NEAR(p.v[i] / exact, 1.0, 1.01 * (n - 1) * 0x1p-24 + 1e-12) << x[i] << "^" << n;
        }
      }
    }
  }
  // Anything else takes exp2(y log2 x): fractions, 0, negative, too large,
  // infinite, NaN, or lanes that differ.
  const float nan = NAN, inf = INFINITY;
  for (float y : { 40.5f, 0.0f, -0.0f, -2.0f, 1025.0f, 4096.0f, 1e30f, inf, -inf, nan })
  {
    EXPECT_EQ(simd::uniformWholeExponent(vfloat8(y)), 0u) << y;
  }
  const float mixed[8] = { 40, 40, 40, 40, 40, 40, 40, 41 };
  const float mixedNaN[8] = { 40, 40, 40, nan, 40, 40, 40, 40 };
  EXPECT_EQ(simd::uniformWholeExponent(lanes(mixed)), 0u);
  EXPECT_EQ(simd::uniformWholeExponent(lanes(mixedNaN)), 0u);
}

TEST(SIMDBatch, PowWholeOutsideTheFloatRange)
{
  // Past the normal floats, repeated squaring underflows gradually (a
  // subnormal, then 0) and overflows to infinity; x^0 is 1.
  namespace simd = shadelab::simd;
  const float x[8] = { 0.1f, 0.01f, 1e-30f, 0.5f, 2.0f, 10.0f, 1e20f, 0.0f };
  const vfloat8 p40 = simd::powWhole(lanes(x), 40);
  EXPECT_GT(p40.v[0], 0.0f); // 1e-40: subnormal
  EXPECT_LT(p40.v[0], 1.2e-38f);
  EXPECT_NEAR(p40.v[0] / 1e-40, 1.0, 1e-4); // a subnormal keeps ~17 bits here
  EXPECT_EQ(p40.v[1], 0.0f); // 1e-80
  EXPECT_EQ(p40.v[2], 0.0f);
  EXPECT_EQ(p40.v[3], std::ldexp(1.0f, -40)); // exact: powers of two
  EXPECT_EQ(p40.v[4], std::ldexp(1.0f, 40));
  EXPECT_EQ(p40.v[5], INFINITY); // 1e40
  EXPECT_EQ(p40.v[6], INFINITY);
  EXPECT_EQ(p40.v[7], 0.0f);
  const vfloat8 p0 = simd::powWhole(lanes(x), 0);
  for (int i = 0; i < 8; ++i)
  {
    EXPECT_EQ(p0.v[i], 1.0f) << x[i];
  }
}

TEST(SIMDBatch, InversesqrtAgreesWithLibm)
{
  // The hardware estimate plus one Newton step (SIMDFloat8.h): 3e-7 relative
  // over the normal floats, checked log-uniformly from 1e-37 to 3e38.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> exponent(-37.0, 38.4);
  for (int round = 0; round < 4000; ++round)
  {
    float x[8];
    for (int i = 0; i < 8; ++i)
    {
      x[i] = static_cast<float>(std::pow(10.0, exponent(random)));
    }
    const vfloat8 r = shadelab::simd::inversesqrt(lanes(x));
    for (int i = 0; i < 8; ++i)
    {
      EXPECT_NEAR(r.v[i] * std::sqrt(double(x[i])), 1.0, 3e-7) << x[i];
    }
  }
}

TEST(SIMDBatch, SelectsAreLaneByLaneAndKeepNaNOut)
{
  // slSafeNormalize on 8 different vectors, some degenerate: each lane gets
  // its own answer, and a zero, infinite or NaN lane gives the zero vector.
  const float inf = INFINITY, nan = NAN;
  const float x[8] = { 3.0f, 0.0f, inf, nan, 0.0f, 1e-30f, -2.0f, 1.0f };
  const float y[8] = { 4.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f };
  const shadelab::glsl8::vec3 n =
    shadelab::glsl8::slSafeNormalize(shadelab::glsl8::vec3(lanes(x), lanes(y), vfloat8(0.0f)));
  const float expectedX[8] = { 0.6f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, -1.0f, float(1.0 / std::sqrt(2.0)) };
  const float expectedY[8] = { 0.8f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, float(1.0 / std::sqrt(2.0)) };
  for (int i = 0; i < 8; ++i)
  {
    // 3e-7: inversesqrt's accuracy (InversesqrtAgreesWithLibm).
    EXPECT_NEAR(n.x.v[i], expectedX[i], 3e-7) << "lane " << i;
    EXPECT_NEAR(n.y.v[i], expectedY[i], 3e-7) << "lane " << i;
    EXPECT_EQ(n.z.v[i], 0.0f) << "lane " << i;
  }
  // slPow's limits per lane: x <= 0 gives 0 for e > 0 and 1 for e <= 0.
  const float px[8] = { 0.5f, 0.0f, -1.0f, 0.0f, -1.0f, 2.0f, 0.25f, 0.0f };
  const float pe[8] = { 2.0f, 3.0f, 3.0f, 0.0f, -1.0f, 0.5f, 0.0f, -2.0f };
  const vfloat8 p = shadelab::glsl8::slPow(lanes(px), lanes(pe));
  const float expected[8] = { 0.25f, 0.0f, 0.0f, 1.0f, 1.0f, float(std::sqrt(2.0)), 1.0f, 1.0f };
  for (int i = 0; i < 8; ++i)
  {
    EXPECT_NEAR(p.v[i], expected[i], 1e-6) << "lane " << i;
  }
}

TEST(SIMDBatch, SpecularWithinTwiceFloatEvaluationAtEveryShininess)
{
  // The batch compilation's specular factor (the radiance kernel's) against
  // the same formula in double (LightingGLSLDouble.h) from the same float
  // N, L, V, beside the plain float compilation (libm's powf): its largest
  // relative error over the lobe stays within twice the plain float one's.
  // The bounds per shininess are in docs/lighting-cpu.md.
  namespace glsl = shadelab::glsl;
  namespace glsl8 = shadelab::glsl8;
  namespace glsld = shadelab::glsld;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int model : { glsl::SL_MODEL_PHONG, glsl::SL_MODEL_BLINN_PHONG })
  {
    for (float n : { 10.0f, 100.0f, 1000.0f, 2000.0f, 10000.0f, 100000.0f, 40.5f, 2000.5f })
    {
      double worstBatch = 0.0, worstFloat = 0.0;
      for (int round = 0; round < 4000; ++round)
      {
        float lx[8], lz[8], vx[8], vy[8], vz[8];
        for (int i = 0; i < 8; ++i)
        {
          // L at up to 80 degrees; V within 2 lobe widths of the mirror direction.
          const double ti = 1.4 * unit(random), d = 2.0 * unit(random) / std::sqrt(double(n)),
                       phi = 6.283185307179586 * unit(random);
          lx[i] = float(std::sin(ti));
          lz[i] = float(std::cos(ti));
          const glm::dvec3 R(-std::sin(ti), 0.0, std::cos(ti)), T(std::cos(ti), 0.0, std::sin(ti));
          const glm::dvec3 V = std::cos(d) * R + std::sin(d) * (std::cos(phi) * T + std::sin(phi) * glm::dvec3(0, 1, 0));
          vx[i] = float(V.x);
          vy[i] = float(V.y);
          vz[i] = float(V.z);
        }
        const shadelab::simd::vec3x8 N(vfloat8(0.0f), vfloat8(0.0f), vfloat8(1.0f));
        const shadelab::simd::vec3x8 L(lanes(lx), vfloat8(0.0f), lanes(lz));
        const shadelab::simd::vec3x8 V(lanes(vx), lanes(vy), lanes(vz));
        glsl8::slMaterial material;
        material.shininess = vfloat8(n);
        const shadelab::simd::vec3x8 X(vfloat8(1.0f), vfloat8(0.0f), vfloat8(0.0f));
        const vfloat8 batch = glsl8::slSpecularFactor(model, material, N, X, L, V);
        for (int i = 0; i < 8; ++i)
        {
          const glm::vec3 Nf(0.0f, 0.0f, 1.0f), Lf(lx[i], 0.0f, lz[i]), Vf(vx[i], vy[i], vz[i]);
          glsld::slMaterial md;
          md.shininess = n;
          const double exact = glsld::slSpecularFactor(model, md, glm::dvec3(Nf), glm::dvec3(1, 0, 0), glm::dvec3(Lf), glm::dvec3(Vf));
          if (exact < 1e-3)
          {
            continue;
          }
          worstBatch = std::max(worstBatch, std::abs(batch.v[i] - exact) / exact);
          glsl::slMaterial mf;
          mf.shininess = n;
          const double specular = glsl::slSpecularFactor(model, mf, Nf, glm::vec3(1, 0, 0), Lf, Vf);
          worstFloat = std::max(worstFloat, std::abs(specular - exact) / exact);
        }
      }
      std::printf("model %d n %g: batch %.3g, float %.3g relative\n", model, double(n), worstBatch, worstFloat);
      EXPECT_LE(worstBatch, 2.0 * worstFloat) << "model " << model << " n " << n;
    }
  }
}
