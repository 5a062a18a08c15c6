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
/// eye, shininess.
struct ReflectionGeometry
{
  glm::dvec3 N, L, V;
  double n;
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
