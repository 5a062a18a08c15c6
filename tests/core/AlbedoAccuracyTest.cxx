// shadelab::directionalAlbedo (adaptive Gauss-Kronrod in the lobe's frame)
// against closed forms and against an independent quadrature written here:
// composite Gauss-Legendre in the plain spherical coordinates of V, on a grid
// refined geometrically toward the peak (V = R) and toward the kink of
// max(0, R.V)^n, with the BRDF evaluated in double.
#include "LightingTestUtilities.h"

#include "shadelab/Albedo.h"
#include "shadelab/LightingGLSLDouble.h"
#include "shadelab/LightingTables.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

using namespace shadelab;
using namespace shadelab::test;

namespace
{
// 12-point Gauss-Legendre on [-1, 1] (positive half; the rule is symmetric).
constexpr double kX[6] = { 0.1252334085114689, 0.3678314989981802, 0.5873179542866175, 0.7699026741943047,
  0.9041172563704749, 0.9815606342467192 };
constexpr double kW[6] = { 0.2491470458134028, 0.2334925365383548, 0.2031674267230659, 0.1600783285433462,
  0.1069393259953184, 0.0471753363865118 };

template <class F>
double gaussLegendre(const F& f, double a, double b)
{
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  double sum = 0.0;
  for (int i = 0; i < 6; ++i)
  {
    sum += kW[i] * (f(c - h * kX[i]) + f(c + h * kX[i]));
  }
  return sum * h;
}

/// Breakpoints in [low, high]: the ends, every point of @p special and the
/// points at distances 1e-6 * 3^k (k = 0, 1, ...) on either side of each,
/// plus a uniform grid of @p cells pieces.
std::vector<double> graded(double low, double high, const std::vector<double>& special, int cells)
{
  std::vector<double> b{ low, high };
  for (int i = 1; i < cells; ++i)
  {
    b.push_back(low + (high - low) * i / cells);
  }
  for (double p : special)
  {
    b.push_back(p);
    for (double d = 1e-6; d < high - low; d *= 3.0)
    {
      b.push_back(p - d);
      b.push_back(p + d);
    }
  }
  std::vector<double> inside;
  for (double x : b)
  {
    if (x >= low && x <= high)
    {
      inside.push_back(x);
    }
  }
  std::sort(inside.begin(), inside.end());
  inside.erase(std::unique(inside.begin(), inside.end()), inside.end());
  return inside;
}

template <class F>
double composite(const F& f, const std::vector<double>& breaks)
{
  double sum = 0.0;
  for (size_t i = 0; i + 1 < breaks.size(); ++i)
  {
    sum += gaussLegendre(f, breaks[i], breaks[i + 1]);
  }
  return sum;
}

glsl::slMaterial tableMaterial(int model, double n)
{
  // The table's material: k_d = 1 for a model without a specular term, k_s = 1 otherwise.
  const bool lambert = (modelInfo(static_cast<ShadingModel>(model)).reads & kReadsSpecular) == 0;
  glsl::slMaterial m;
  m.ambient = m.emission = glm::vec3(0.0f);
  m.diffuse = glm::vec3(lambert ? 1.0f : 0.0f);
  m.specular = glm::vec3(lambert ? 0.0f : 1.0f);
  m.shininess = static_cast<float>(n);
  return m;
}

/// The independent reference: integral over theta_o in [0, pi/2] and phi_o in
/// [0, pi] (twice, by symmetry) of f_r cos(theta_o) sin(theta_o).
double referenceAlbedo(int model, double n, double thetaI)
{
  glsld::slMaterial m;
  m.ambient = m.emission = glm::dvec3(0.0);
  const glsl::slMaterial f = tableMaterial(model, n);
  m.diffuse = glm::dvec3(f.diffuse);
  m.specular = glm::dvec3(f.specular);
  m.shininess = n;
  const glm::dvec3 N(0.0, 0.0, 1.0), L(std::sin(thetaI), 0.0, std::cos(thetaI));
  const double halfPi = 0.5 * kPi;
  // R = (-sin, 0, cos): the peak is at theta_o = theta_i, phi_o = pi; R.V = 0
  // where cos(phi_o) = cos(theta_i) cos(theta_o) / (sin(theta_i) sin(theta_o)).
  const std::vector<double> thetaBreaks = graded(0.0, halfPi, { thetaI, halfPi - thetaI }, 16);
  auto ring = [&](double thetaO) {
    std::vector<double> special{ kPi };
    const double c = std::cos(thetaI) * std::cos(thetaO) / std::max(1e-300, std::sin(thetaI) * std::sin(thetaO));
    if (c > -1.0 && c < 1.0)
    {
      special.push_back(std::acos(c));
    }
    auto g = [&](double phiO) {
      const glm::dvec3 V(std::sin(thetaO) * std::cos(phiO), std::sin(thetaO) * std::sin(phiO), std::cos(thetaO));
      const glm::dvec3 r = glsld::slBRDF(model, m, N, L, V);
      return (r.x + r.y + r.z) / 3.0;
    };
    return composite(g, graded(0.0, kPi, special, 16)) * std::cos(thetaO) * std::sin(thetaO);
  };
  return 2.0 * composite(ring, thetaBreaks);
}

const std::vector<int> kModels = allModels();
} // namespace

TEST(AlbedoAccuracy, ClosedFormsAtEveryAngleAndNormalIncidence)
{
  for (double n : { 0.0, 0.5, 1.0, 20.0, 100.0, 500.0, 2000.0, 10000.0 })
  {
    auto albedo = [n](int model, double degrees) {
      return directionalAlbedo(model, tableMaterial(model, n), radians(degrees));
    };
    for (double degrees : { 0.0, 30.0, 60.0, 89.0, 89.9 })
    {
      // Lambert: f_r = k_d = 1 reflects pi; rho / pi reflects rho = 1.
      EXPECT_NEAR(albedo(glsl::SL_MODEL_LAMBERT, degrees), kPi, 1e-6);
      EXPECT_NEAR(albedo(glsl::SL_MODEL_LAMBERT_NORMALIZED, degrees), 1.0, 1e-6);
    }
    // Phong at normal incidence: integral of cos^n cos dw = 2 pi / (n + 2),
    // so the normalised (n + 2) / (2 pi) cos^n reflects exactly 1; so does
    // the exactly normalised Blinn-Phong.
    EXPECT_NEAR(albedo(glsl::SL_MODEL_PHONG, 0.0), 2.0 * kPi / (n + 2.0), 1e-6) << n;
    EXPECT_NEAR(albedo(glsl::SL_MODEL_PHONG_NORMALIZED, 0.0), 1.0, 1e-6) << n;
    EXPECT_NEAR(albedo(glsl::SL_MODEL_BLINN_PHONG_NORMALIZED, 0.0), 1.0, 1e-6) << n;
  }
}

TEST(AlbedoAccuracy, WithinOneTenThousandthOfAnIndependentQuadrature)
{
  std::vector<double> worst(kLightingModelCount, 0.0);
  for (int model : kModels)
  {
    for (double n : { 0.0, 0.5, 1.0, 5.0, 20.0, 100.0, 500.0, 2000.0, 10000.0 })
    {
      for (double degrees : { 0.0, 20.0, 45.0, 70.0, 85.0, 89.0, 89.9 })
      {
        const double a = directionalAlbedo(model, tableMaterial(model, n), radians(degrees));
        const double reference = referenceAlbedo(model, n, radians(degrees));
        EXPECT_NEAR(a, reference, 1e-4) << "model " << model << " n = " << n << " at " << degrees << " degrees";
        worst[model] = std::max(worst[model], std::abs(a - reference));
        if (modelInfo(static_cast<ShadingModel>(model)).normalized)
        {
          EXPECT_LE(a, 1.0 + 1e-6) << "model " << model << " n = " << n << " at " << degrees << " degrees";
        }
      }
    }
  }
  for (int model : kModels)
  {
    std::printf("largest difference, model %d: %.3g\n", model, worst[model]);
  }
}
