// The microfacet, Oren-Nayar and anisotropic models against computations
// written here in angles: the distributions' projected area, reciprocity,
// Oren-Nayar's and the anisotropic models' special cases, the single-
// scattering GGX white furnace, and Beckmann's rational Lambda.
#include "LightingTestUtilities.h"
#include "Quadrature.h"

#include "shadelab/Albedo.h"
#include "shadelab/LightingGLSLDouble.h"
#include "shadelab/LightingTables.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

using namespace shadelab;
using namespace shadelab::test;

namespace
{
/// A material with every parameter set: k_d, k_s, n, the roughnesses, ior.
slMaterial material(float kd, float ks, float roughness, float roughnessX, float roughnessY, float ior = 1.5f)
{
  slMaterial m = unitMaterial(20.0f);
  m.diffuse = glm::vec3(kd);
  m.specular = glm::vec3(ks);
  m.roughness = roughness;
  m.roughnessX = roughnessX;
  m.roughnessY = roughnessY;
  m.ior = ior;
  return m;
}

/// A random unit vector at least @p minCos above the plane z = 0.
glm::vec3 randomAbove(std::mt19937& rng, double minCos = 0.05)
{
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double z = minCos + (1.0 - minCos) * u(rng);
  return polar(std::acos(z), 2.0 * kPi * u(rng));
}

/// The mean of R, G and B.
double grey(const glm::vec3& c)
{
  return (c.x + c.y + c.z) / 3.0;
}

/// The single-scattering GGX BRDF with F = 1, in angles: D G2 / (4 ci co)
/// with D = alpha^2 / (pi cos^4(theta_h) (alpha^2 + tan^2(theta_h))^2) and the
/// height-correlated G2 = 1 / (1 + Lambda_i + Lambda_o),
/// Lambda = (sqrt(1 + alpha^2 tan^2(theta)) - 1) / 2.
double ggxWhite(double alpha, const glm::dvec3& L, const glm::dvec3& V)
{
  const glm::dvec3 H = glm::normalize(L + V);
  const double cosH = H.z, tan2H = (1.0 - cosH * cosH) / (cosH * cosH);
  const double D = alpha * alpha / (kPi * std::pow(cosH, 4.0) * std::pow(alpha * alpha + tan2H, 2.0));
  auto lambda = [alpha](double c) { return 0.5 * (std::sqrt(1.0 + alpha * alpha * (1.0 - c * c) / (c * c)) - 1.0); };
  return D / (1.0 + lambda(L.z) + lambda(V.z)) / (4.0 * L.z * V.z);
}

/// Integral of ggxWhite cos(theta_o) over the hemisphere of V, in V's own
/// spherical coordinates, on grids refined toward the mirror direction.
double ggxFurnace(double alpha, double thetaI)
{
  const glm::dvec3 L(std::sin(thetaI), 0.0, std::cos(thetaI));
  auto ring = [&](double thetaO) {
    auto g = [&](double phiO) {
      const glm::dvec3 V(std::sin(thetaO) * std::cos(phiO), std::sin(thetaO) * std::sin(phiO), std::cos(thetaO));
      return ggxWhite(alpha, L, V);
    };
    return composite(g, graded(0.0, kPi, { kPi }, 32, 1e-4 * alpha)) * std::cos(thetaO) * std::sin(thetaO);
  };
  return 2.0 * composite(ring, graded(0.0, 0.5 * kPi, { thetaI }, 32, 1e-4 * alpha));
}
} // namespace

TEST(MicrofacetModels, DistributionsIntegrateToOneOverProjectedArea)
{
  // Integral of D(h) cos(theta_h) dw_h = 2 pi integral of D cos sin dtheta.
  for (double alpha : { 0.01, 0.05, 0.2, 0.5, 1.0 })
  {
    const std::vector<double> grid = graded(0.0, 0.5 * kPi, { 0.0 }, 32, 1e-3 * alpha);
    auto projected = [&](auto distribution) {
      return 2.0 * kPi * composite([&](double t) { return distribution(std::cos(t)) * std::cos(t) * std::sin(t); }, grid);
    };
    EXPECT_NEAR(projected([&](double c) { return glsld::slGGXDistribution(c, alpha); }), 1.0, 1e-7) << alpha;
    EXPECT_NEAR(projected([&](double c) { return glsld::slBeckmannDistribution(c, alpha); }), 1.0, 1e-7) << alpha;
  }
}

TEST(MicrofacetModels, ReciprocityForEveryPhysicallyBasedModel)
{
  // f(L, V) = f(V, L) at random directions above the surface and random
  // tangents, for every model but the lecture Phong and Blinn-Phong, whose
  // literal BRDF k_s S / cos(theta_i) divides by the incident cosine only.
  std::mt19937 rng(7);
  const slMaterial m = material(0.6f, 0.4f, 0.3f, 0.2f, 0.5f);
  for (int model : allModels())
  {
    const bool lecture = model == glsl::SL_MODEL_PHONG || model == glsl::SL_MODEL_BLINN_PHONG;
    double worst = 0.0;
    for (int i = 0; i < 2000; ++i)
    {
      const glm::vec3 N(0.0f, 0.0f, 1.0f), L = randomAbove(rng), V = randomAbove(rng);
      const glm::vec3 T = randomAbove(rng, -1.0);
      const double a = grey(glsl::slBRDF(model, m, N, T, L, V)), b = grey(glsl::slBRDF(model, m, N, T, V, L));
      worst = std::max(worst, std::abs(a - b) / std::max({ std::abs(a), std::abs(b), 1e-6 }));
    }
    if (lecture)
    {
      EXPECT_GT(worst, 0.1) << kLightingModels[model].name;
    }
    else
    {
      EXPECT_LT(worst, 1e-4) << kLightingModels[model].name;
    }
  }
}

TEST(MicrofacetModels, OrenNayarAtZeroRoughnessIsNormalisedLambert)
{
  std::mt19937 rng(3);
  slMaterial m = material(0.0f, 0.0f, 0.0f, 0.0f, 0.0f);
  m.diffuse = glm::vec3(0.2f, 0.5f, 0.8f);
  for (int i = 0; i < 1000; ++i)
  {
    const glm::vec3 N(0.0f, 0.0f, 1.0f), L = randomAbove(rng), V = randomAbove(rng, -1.0);
    const glm::vec3 f = glsl::slBRDF(glsl::SL_MODEL_OREN_NAYAR, m, N, glm::vec3(1.0f, 0.0f, 0.0f), L, V);
    EXPECT_NEAR(f.x, 0.2 / kPi, 1e-7);
    EXPECT_NEAR(f.y, 0.5 / kPi, 1e-7);
    EXPECT_NEAR(f.z, 0.8 / kPi, 1e-7);
  }
}

TEST(MicrofacetModels, AnisotropicModelsWithEqualRoughnessesAreTheirIsotropicForms)
{
  std::mt19937 rng(11);
  const double kd = 0.3, ks = 0.7, ior = 1.8, f0 = std::pow((ior - 1.0) / (ior + 1.0), 2.0);
  for (double alpha : { 0.1, 0.3, 0.7 })
  {
    const slMaterial m = material(float(kd), float(ks), 0.0f, float(alpha), float(alpha), float(ior));
    const double n = 2.0 / (alpha * alpha) - 2.0;
    for (int i = 0; i < 500; ++i)
    {
      const glm::vec3 N(0.0f, 0.0f, 1.0f), L = randomAbove(rng), V = randomAbove(rng), T = randomAbove(rng, -1.0);
      const glm::dvec3 l(L), v(V), h = glm::normalize(l + v);
      const double ci = l.z, co = v.z, cosH = h.z, tan2H = (1.0 - cosH * cosH) / (cosH * cosH), lh = glm::dot(l, h);
      // Ward (1992), isotropic: exp(-tan^2(theta_h) / alpha^2) / (4 pi alpha^2 sqrt(ci co)).
      const double ward = kd / kPi + ks * std::exp(-tan2H / (alpha * alpha)) / (4.0 * kPi * alpha * alpha * std::sqrt(ci * co));
      // Ashikhmin-Shirley (2000), nu = nv = n.
      const double fresnel = f0 + (1.0 - f0) * std::pow(1.0 - lh, 5.0);
      const double as = kd * 28.0 / (23.0 * kPi) * (1.0 - f0) * (1.0 - std::pow(1.0 - ci / 2.0, 5.0)) *
          (1.0 - std::pow(1.0 - co / 2.0, 5.0)) +
        ks * (n + 1.0) / (8.0 * kPi) * std::pow(cosH, n) * fresnel / (lh * std::max(ci, co));
      EXPECT_NEAR(grey(glsl::slBRDF(glsl::SL_MODEL_WARD, m, N, T, L, V)), ward, 1e-4 * ward + 1e-7);
      EXPECT_NEAR(grey(glsl::slBRDF(glsl::SL_MODEL_ASHIKHMIN_SHIRLEY, m, N, T, L, V)), as, 1e-4 * as + 1e-7);
    }
  }
}

TEST(MicrofacetModels, BeckmannRationalLambdaWithinFourTenthsOfAPercent)
{
  // Smith's G1 = 1 / (1 + Lambda) from the rational Lambda against the exact
  // Lambda = (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)), a = cos / (alpha sin).
  double worst = 0.0;
  for (double alpha : { 0.05, 0.2, 0.5, 1.0 })
  {
    for (int i = 1; i < 2000; ++i)
    {
      const double c = i / 2000.0, a = c / (alpha * std::sqrt(1.0 - c * c));
      const double exact = 0.5 * (std::erf(a) - 1.0) + std::exp(-a * a) / (2.0 * a * std::sqrt(kPi));
      const double g1 = 1.0 / (1.0 + glsld::slBeckmannLambda(c, alpha)), g1Exact = 1.0 / (1.0 + exact);
      worst = std::max(worst, std::abs(g1 / g1Exact - 1.0));
    }
  }
  EXPECT_LT(worst, 0.004);
  std::printf("largest relative difference of G1: %.3g\n", worst);
}

TEST(MicrofacetModels, SingleScatteringGGXWhiteFurnace)
{
  // F = 1 (ior 1e7 gives F0 = 1 - 4e-7), k_d = 0, k_s = 1: the albedo is
  // the energy single scattering keeps, below 1 and falling with roughness.
  const slMaterial m = material(0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1e7f);
  std::printf("alpha   E(0 deg)  E(45 deg)  E(75 deg)   (independent quadrature)\n");
  for (double degrees : { 0.0, 45.0, 75.0 })
  {
    double previous = 1.0;
    for (double alpha : { 0.1, 0.25, 0.5, 0.75, 1.0 })
    {
      slMaterial rough = m;
      rough.roughness = float(alpha);
      const double expected = ggxFurnace(alpha, radians(degrees));
      const double albedo = directionalAlbedo(glsl::SL_MODEL_COOK_TORRANCE_GGX, rough, radians(degrees));
      EXPECT_NEAR(albedo, expected, 1e-3) << alpha << " at " << degrees << " degrees";
      EXPECT_LT(expected, previous + 1e-9) << alpha << " at " << degrees << " degrees";
      previous = expected;
    }
    EXPECT_LT(previous, 0.95) << "roughness 1 at " << degrees << " degrees";
  }
  // At alpha = 1 and normal incidence D = 1 / pi and G2 = 2 co / (1 + co), so
  // E = integral over [0, 1] of co / (1 + co) dco = 1 - ln 2.
  EXPECT_NEAR(ggxFurnace(1.0, 0.0), 1.0 - std::log(2.0), 1e-9);
  for (double alpha : { 0.1, 0.25, 0.5, 0.75, 1.0 })
  {
    std::printf("%.2f    %.4f    %.4f     %.4f\n", alpha, ggxFurnace(alpha, 0.0), ggxFurnace(alpha, radians(45.0)),
      ggxFurnace(alpha, radians(75.0)));
  }
}
