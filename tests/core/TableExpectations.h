#ifndef shadelab_tests_TableExpectations_h
#define shadelab_tests_TableExpectations_h
// What each row of LightingTables.h must compute, written from first
// principles in double (never through slLighting.glsl). LightingTablesTest
// requires an entry for every lighting model and every light type, so a new
// row without its expected values fails the tests.

#include "LightingTestUtilities.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>

namespace shadelab
{
namespace test
{

/// Unit normal, unit direction toward the light, unit direction toward the
/// eye, shininess; the unit tangent X (orthogonal to N), the roughness
/// alpha, the anisotropic pair along X and Y = N x X, the index of refraction.
struct ReflectionGeometry
{
  glm::dvec3 N, L, V;
  double n;
  glm::dvec3 X;
  double alpha, alphaX, alphaY, ior;
};

/// The diffuse and specular reflection factors (f_r cos theta_i split into
/// its k_d and k_s parts) of slDiffuseFactor() and slSpecularFactor().
struct ReflectionFactors
{
  double diffuse, specular;
};

using ModelExpectation = std::function<ReflectionFactors(const ReflectionGeometry&)>;

namespace detail
{
inline double cosTheta(const ReflectionGeometry& g)
{
  return glm::dot(g.N, g.L);
}
/// max(0, R.V)^n with R the mirror of L about N; 0 behind the surface.
inline double phongLobe(const ReflectionGeometry& g)
{
  const glm::dvec3 R = 2.0 * cosTheta(g) * g.N - g.L;
  return cosTheta(g) > 0.0 ? std::pow(std::max(0.0, glm::dot(R, g.V)), g.n) : 0.0;
}
/// max(0, N.H)^n with H halfway between L and V; 0 behind the surface.
inline double blinnLobe(const ReflectionGeometry& g)
{
  const glm::dvec3 H = glm::normalize(g.L + g.V);
  return cosTheta(g) > 0.0 ? std::pow(std::max(0.0, glm::dot(g.N, H)), g.n) : 0.0;
}
/// Giesen's exact Blinn-Phong normalisation.
inline double blinnNormalization(double n)
{
  return (n + 2.0) * (n + 4.0) / (8.0 * kPi * (std::pow(2.0, -0.5 * n) + n));
}

/// Polar angle from N and azimuth from X of a unit vector.
struct Angles
{
  double theta, phi;
};
inline Angles anglesOf(const ReflectionGeometry& g, const glm::dvec3& w)
{
  const glm::dvec3 Y = glm::cross(g.N, g.X);
  return { std::acos(std::clamp(glm::dot(g.N, w), -1.0, 1.0)), std::atan2(glm::dot(w, Y), glm::dot(w, g.X)) };
}
inline glm::dvec3 halfVector(const ReflectionGeometry& g)
{
  return glm::normalize(g.L + g.V);
}
/// Schlick's Fresnel at cosine c, F0 = ((ior - 1) / (ior + 1))^2.
inline double schlick(double ior, double c)
{
  const double f0 = std::pow((ior - 1.0) / (ior + 1.0), 2.0);
  return f0 + (1.0 - f0) * std::pow(1.0 - c, 5.0);
}
/// A microfacet BRDF's specular factor f_r cos theta_i = D G2 F / (4 co):
/// zero unless both directions are above the surface.
inline double microfacet(const ReflectionGeometry& g, double D, double lambdaI, double lambdaO)
{
  const double ci = cosTheta(g), co = glm::dot(g.N, g.V);
  if (ci <= 0.0 || co <= 0.0)
  {
    return 0.0;
  }
  const double G2 = 1.0 / (1.0 + lambdaI + lambdaO);
  return D * G2 * schlick(g.ior, glm::dot(g.V, halfVector(g))) / (4.0 * co);
}
/// GGX in slope space: 1 / (pi a^2 cos^4 (1 + tan^2 / a^2)^2); Smith's
/// Lambda (-1 + sqrt(1 + a^2 tan^2)) / 2 (Heitz 2014).
inline double ggx(const ReflectionGeometry& g)
{
  const double a = g.alpha, th = anglesOf(g, halfVector(g)).theta, t2 = std::pow(std::tan(th), 2.0);
  const double D = 1.0 / (kPi * a * a * std::pow(std::cos(th), 4.0) * std::pow(1.0 + t2 / (a * a), 2.0));
  auto lambda = [&](const glm::dvec3& w) {
    return (-1.0 + std::sqrt(1.0 + a * a * std::pow(std::tan(anglesOf(g, w).theta), 2.0))) / 2.0;
  };
  return microfacet(g, D, lambda(g.L), lambda(g.V));
}
/// Beckmann: exp(-tan^2 / a^2) / (pi a^2 cos^4); Lambda in Walter et al.'s
/// rational form of a = 1 / (alpha tan theta) (2007, eq. 27).
inline double beckmann(const ReflectionGeometry& g)
{
  const double a = g.alpha, th = anglesOf(g, halfVector(g)).theta;
  const double D = std::exp(-std::pow(std::tan(th) / a, 2.0)) / (kPi * a * a * std::pow(std::cos(th), 4.0));
  auto lambda = [&](const glm::dvec3& w) {
    const double x = 1.0 / (a * std::tan(anglesOf(g, w).theta));
    return x < 1.6 ? (1.0 - 1.259 * x + 0.396 * x * x) / (3.535 * x + 2.181 * x * x) : 0.0;
  };
  return microfacet(g, D, lambda(g.L), lambda(g.V));
}
/// Oren-Nayar's qualitative model with sigma = alpha, in angles.
inline double orenNayar(const ReflectionGeometry& g)
{
  const Angles i = anglesOf(g, g.L), o = anglesOf(g, g.V);
  const double s2 = g.alpha * g.alpha, A = 1.0 - 0.5 * s2 / (s2 + 0.33), B = 0.45 * s2 / (s2 + 0.09);
  const double a = std::max(i.theta, o.theta), b = std::min(i.theta, o.theta);
  return std::max(0.0, cosTheta(g)) / kPi * (A + B * std::max(0.0, std::cos(i.phi - o.phi)) * std::sin(a) * std::tan(b));
}
/// Ward's anisotropic Gaussian, in the angles of H.
inline double ward(const ReflectionGeometry& g)
{
  const double ci = cosTheta(g), co = glm::dot(g.N, g.V);
  if (ci <= 0.0 || co <= 0.0)
  {
    return 0.0;
  }
  const Angles h = anglesOf(g, halfVector(g));
  const double e = -std::pow(std::tan(h.theta), 2.0) *
    (std::pow(std::cos(h.phi) / g.alphaX, 2.0) + std::pow(std::sin(h.phi) / g.alphaY, 2.0));
  return std::exp(e) / (4.0 * kPi * g.alphaX * g.alphaY * std::sqrt(ci * co)) * ci;
}
/// Ashikhmin-Shirley's specular lobe with n = 2 / alpha^2 - 2, in the angles of H.
inline double ashikhminShirley(const ReflectionGeometry& g)
{
  const double ci = cosTheta(g), co = glm::dot(g.N, g.V);
  if (ci <= 0.0 || co <= 0.0)
  {
    return 0.0;
  }
  const double nu = 2.0 / (g.alphaX * g.alphaX) - 2.0, nv = 2.0 / (g.alphaY * g.alphaY) - 2.0;
  const glm::dvec3 H = halfVector(g);
  const Angles h = anglesOf(g, H);
  const double exponent = nu * std::pow(std::cos(h.phi), 2.0) + nv * std::pow(std::sin(h.phi), 2.0);
  const double LH = glm::dot(g.L, H);
  return std::sqrt((nu + 1.0) * (nv + 1.0)) / (8.0 * kPi) * std::pow(std::cos(h.theta), exponent) *
    schlick(g.ior, LH) / (LH * std::max(ci, co)) * ci;
}
/// Ashikhmin-Shirley's diffuse term over k_d, times cos theta_i.
inline double ashikhminShirleyDiffuse(const ReflectionGeometry& g)
{
  const double ci = std::max(0.0, cosTheta(g)), co = std::max(0.0, glm::dot(g.N, g.V));
  const double f0 = std::pow((g.ior - 1.0) / (g.ior + 1.0), 2.0);
  return 28.0 / (23.0 * kPi) * (1.0 - f0) * (1.0 - std::pow(1.0 - ci / 2.0, 5.0)) *
    (1.0 - std::pow(1.0 - co / 2.0, 5.0)) * ci;
}
} // namespace detail

/// Expected reflection factors per lighting model, by scene-file name.
inline const std::map<std::string, ModelExpectation>& modelExpectations()
{
  using namespace detail;
  static const std::map<std::string, ModelExpectation> table{
    { "lambert", [](const ReflectionGeometry& g) { return ReflectionFactors{ std::max(0.0, cosTheta(g)), 0.0 }; } },
    { "phong",
      [](const ReflectionGeometry& g) { return ReflectionFactors{ std::max(0.0, cosTheta(g)), phongLobe(g) }; } },
    { "blinn-phong",
      [](const ReflectionGeometry& g) { return ReflectionFactors{ std::max(0.0, cosTheta(g)), blinnLobe(g) }; } },
    { "lambert-normalized",
      [](const ReflectionGeometry& g) { return ReflectionFactors{ std::max(0.0, cosTheta(g)) / kPi, 0.0 }; } },
    { "phong-normalized",
      [](const ReflectionGeometry& g) {
        return ReflectionFactors{ std::max(0.0, cosTheta(g)) / kPi,
          (g.n + 2.0) / (2.0 * kPi) * phongLobe(g) * cosTheta(g) };
      } },
    { "blinn-phong-normalized",
      [](const ReflectionGeometry& g) {
        return ReflectionFactors{ std::max(0.0, cosTheta(g)) / kPi,
          blinnNormalization(g.n) * blinnLobe(g) * cosTheta(g) };
      } },
    { "cook-torrance-ggx",
      [](const ReflectionGeometry& g) { return ReflectionFactors{ std::max(0.0, cosTheta(g)) / kPi, ggx(g) }; } },
    { "cook-torrance-beckmann",
      [](const ReflectionGeometry& g) { return ReflectionFactors{ std::max(0.0, cosTheta(g)) / kPi, beckmann(g) }; } },
    { "oren-nayar", [](const ReflectionGeometry& g) { return ReflectionFactors{ orenNayar(g), 0.0 }; } },
    { "ward",
      [](const ReflectionGeometry& g) { return ReflectionFactors{ std::max(0.0, cosTheta(g)) / kPi, ward(g) }; } },
    { "ashikhmin-shirley",
      [](const ReflectionGeometry& g) {
        return ReflectionFactors{ ashikhminShirleyDiffuse(g), ashikhminShirley(g) };
      } },
  };
  return table;
}

/// A light seen from point P: the unit direction toward it (zero: none) and
/// the fraction of it that reaches P.
struct ExpectedIncidence
{
  glm::dvec3 L;
  double reach;
};

/// The light used for every type: at (0, 0, 4), travelling along
/// (0, 0, -1), attenuation (1, 0.1, 0.02), a 40 degree cutoff with a 10
/// degree edge and exponent 2 (a type reads only the values it takes).
inline slLight expectationLight(int type)
{
  slLight l = whiteLight(type);
  l.position = glm::vec3(0.0f, 0.0f, 4.0f);
  l.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  l.attenuation = glm::vec3(1.0f, 0.1f, 0.02f);
  l.cosCutoff = static_cast<float>(std::cos(radians(40.0)));
  l.cosInner = static_cast<float>(std::cos(radians(30.0)));
  l.exponent = 2.0f;
  return l;
}

using LightTypeExpectation = std::function<ExpectedIncidence(const glm::dvec3& P)>;

/// Expected incidence of expectationLight() per light type, by scene-file name.
inline const std::map<std::string, LightTypeExpectation>& lightTypeExpectations()
{
  static const glm::dvec3 position(0.0, 0.0, 4.0);
  static const auto attenuation = [](double d) { return std::min(1.0, 1.0 / (1.0 + 0.1 * d + 0.02 * d * d)); };
  static const std::map<std::string, LightTypeExpectation> table{
    { "directional", [](const glm::dvec3&) { return ExpectedIncidence{ glm::dvec3(0.0, 0.0, 1.0), 1.0 }; } },
    { "point",
      [](const glm::dvec3& P) {
        const double d = glm::length(position - P);
        return ExpectedIncidence{ (position - P) / d, attenuation(d) };
      } },
    { "spot",
      [](const glm::dvec3& P) {
        const double d = glm::length(position - P);
        const glm::dvec3 L = (position - P) / d;
        const double angle = std::acos(std::min(1.0, L.z)) * 180.0 / kPi; // of -L from the axis (0, 0, -1)
        double cone = 0.0;
        if (angle <= 40.0)
        {
          const double c = std::cos(angle * kPi / 180.0), c0 = std::cos(radians(40.0)), c1 = std::cos(radians(30.0));
          const double t = std::clamp((c - c0) / (c1 - c0), 0.0, 1.0);
          cone = t * t * (3.0 - 2.0 * t) * c * c; // smoothstep edge times cos^2
        }
        return ExpectedIncidence{ L, attenuation(d) * cone };
      } },
    { "ambient", [](const glm::dvec3&) { return ExpectedIncidence{ glm::dvec3(0.0), 1.0 }; } },
  };
  return table;
}

} // namespace test
} // namespace shadelab

#endif
