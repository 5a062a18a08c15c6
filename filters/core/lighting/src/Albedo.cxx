#include "shadelab/Albedo.h"

#include "shadelab/LightingGLSLDouble.h"
#include "shadelab/LightingTables.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace shadelab
{

namespace
{
constexpr double kPi = 3.14159265358979323846;

// 15-point Kronrod nodes on [-1, 1] (the odd ones are the 7-point Gauss
// nodes) and weights, from QUADPACK.
constexpr double kNodes[8] = { 0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
  0.864864423359769072789712788640926, 0.741531185599394439863864773280788, 0.586087235467691130294144845693013,
  0.405845151377397166906606412076961, 0.207784955007898467600689403773245, 0.0 };
constexpr double kKronrod[8] = { 0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
  0.104790010322250183839876322541518, 0.140653259715525918745189590510238, 0.169004726639267902826583426598550,
  0.190350578064785409913256402421014, 0.204432940075298892414161999234649, 0.209482141084727828012999174891714 };
constexpr double kGauss[4] = { 0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
  0.381830050505118944950369775488975, 0.417959183673469387755102040816327 };

constexpr int kMaxDepth = 40;

/// Integral of @p f over [a, b], bisecting until |K15 - G7| <= @p tolerance
/// (each half gets half of it).
template <class F>
double adaptive(const F& f, double a, double b, double tolerance, int depth = 0)
{
  const double centre = 0.5 * (a + b), half = 0.5 * (b - a);
  const double middle = f(centre);
  double kronrod = kKronrod[7] * middle, gauss = kGauss[3] * middle;
  for (int i = 0; i < 7; ++i)
  {
    const double sum = f(centre - half * kNodes[i]) + f(centre + half * kNodes[i]);
    kronrod += kKronrod[i] * sum;
    if (i % 2 == 1)
    {
      gauss += kGauss[i / 2] * sum;
    }
  }
  kronrod *= half;
  gauss *= half;
  if (std::abs(kronrod - gauss) <= tolerance || depth >= kMaxDepth)
  {
    return kronrod;
  }
  return adaptive(f, a, centre, 0.5 * tolerance, depth + 1) + adaptive(f, centre, b, 0.5 * tolerance, depth + 1);
}

/// Integral over [0, end] of @p f split at @p breaks (ascending, those inside).
template <class F>
double piecewise(const F& f, const std::vector<double>& breaks, double end, double tolerance)
{
  double sum = 0.0, start = 0.0;
  for (double b : breaks)
  {
    if (b > start && b < end)
    {
      sum += adaptive(f, start, b, tolerance * (b - start) / end);
      start = b;
    }
  }
  // The last piece ends at the horizon, where Ward's f_r cos(theta_o) goes
  // as the square root of cos(theta_o): with t = end - s^2 the integrand
  // becomes smooth there (and stays smooth for the other models).
  const double width = std::sqrt(end - start);
  auto bySquare = [&](double s) { return f(end - s * s) * 2.0 * s; };
  return sum + adaptive(bySquare, 0.0, width, tolerance * (end - start) / end);
}
} // namespace

double directionalAlbedo(int model, const glsl::slMaterial& material, double thetaI)
{
  glsld::slMaterial m;
#define SHADELAB_COPY(type, field, ...) m.field = material.field;
  SHADELAB_MATERIAL_PARAMETERS(SHADELAB_COPY)
#undef SHADELAB_COPY
  const double sinI = std::sin(thetaI), cosI = std::cos(thetaI);
  // The tangent X is +x: L lies in the plane of X and N.
  const glm::dvec3 N(0.0, 0.0, 1.0), X(1.0, 0.0, 0.0), L(sinI, 0.0, cosI);
  const SpecularLobe lobe = modelInfo(static_cast<ShadingModel>(model)).lobe;
  const bool blinn = lobe != SpecularLobe::None && lobe != SpecularLobe::Mirror;

  // f_r cos(theta_o) for V toward the eye, mean of R, G, B.
  auto integrand = [&](const glm::dvec3& V) {
    const glm::dvec3 f = glsld::slBRDF(model, m, N, X, L, V);
    return (f.x + f.y + f.z) / 3.0 * std::max(0.0, V.z);
  };

  // Polar breakpoints: the lobe's width times 1, 2, 4, ... and, for Phong,
  // the kink of max(0, R.V)^n at a right angle from R. The width of a power
  // n of a cosine is about 1 / sqrt(n + 1); of a microfacet lobe, its
  // (smallest) roughness alpha.
  double width = 1.0 / std::sqrt(m.shininess + 1.0);
  if (lobe == SpecularLobe::GGX || lobe == SpecularLobe::Beckmann)
  {
    width = std::max<double>(m.roughness, glsld::SL_MIN_ROUGHNESS);
  }
  if (lobe == SpecularLobe::Ward || lobe == SpecularLobe::AshikhminShirley)
  {
    width = std::max<double>(std::min(m.roughnessX, m.roughnessY), glsld::SL_MIN_ROUGHNESS);
  }
  std::vector<double> breaks;
  for (double b = 0.25 * width; b < kPi; b *= 2.0)
  {
    breaks.push_back(b);
  }
  if (!blinn)
  {
    breaks.push_back(0.5 * kPi);
  }
  if (lobe == SpecularLobe::AshikhminShirley)
  {
    // Its exponent is taken as the mean of nu and nv where
    // 1 - (N.H)^2 <= SL_MIN_COS_THETA: a small step at sin(t) = 1e-3 that
    // the bisection chased 40 levels deep at every azimuth (at 89 degrees
    // 311,415 evaluations of f_r without this break, 50,160 with it).
    breaks.push_back(std::asin(std::sqrt(glsld::SL_MIN_COS_THETA)));
  }
  std::sort(breaks.begin(), breaks.end());

  // Values of N.V where a halfway model's f_r has a kink or a step, which
  // become breaks of the polar integral (about N, in H, they are curves
  // that the bisection would chase): Ashikhmin-Shirley divides by
  // max(N.L, N.V); the approximation of Beckmann's Lambda drops to 0 where
  // cot(theta_o) / alpha reaches 1.6 (from -6e-5: a small step). For
  // Ashikhmin-Shirley that took the time of 10 angles from 0.46 s to 0.10 s.
  std::vector<double> kinkElevations;
  if (lobe == SpecularLobe::AshikhminShirley)
  {
    kinkElevations.push_back(cosI);
  }
  if (lobe == SpecularLobe::Beckmann)
  {
    const double cot = 1.6 * std::max<double>(m.roughness, glsld::SL_MIN_ROUGHNESS);
    kinkElevations.push_back(cot / std::sqrt(1.0 + cot * cot));
  }

  // The frame of the pole: R with T1 in the plane of incidence (N.T1 =
  // sin theta_i) for the Phong models; N for Blinn-Phong's H.
  const glm::dvec3 R(-sinI, 0.0, cosI), T1(cosI, 0.0, sinI), T2(0.0, 1.0, 0.0);
  auto overAzimuth = [&](double phi, double tolerance) {
    const double cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    // N.V = A cos(t - delta) (Phong, t the angle from R) or A cos(2t - delta)
    // (Blinn-Phong, t the angle of H from N): the horizon is at
    // t = pi/2 + delta, or half that.
    const double delta = std::atan2(sinI * cosPhi, cosI);
    if (lobe == SpecularLobe::None)
    {
      // The diffuse models, about N: Oren-Nayar's kinks lie on lines of
      // these coordinates, at theta_o = theta_i (where its alpha and beta
      // swap) and at the azimuth's right angle (max(0, cos(phi_o - phi_i)),
      // where the outer integral is split). About R they are curves, which
      // the bisection chased: 60 ms an angle instead of under 1.
      auto f = [&](double t) {
        const glm::dvec3 V(std::sin(t) * cosPhi, std::sin(t) * sinPhi, std::cos(t));
        return integrand(V) * std::sin(t);
      };
      return piecewise(f, std::vector<double>{ thetaI }, 0.5 * kPi, tolerance);
    }
    if (blinn)
    {
      auto f = [&](double t) {
        const glm::dvec3 H(std::sin(t) * cosPhi, std::sin(t) * sinPhi, std::cos(t));
        const double LdotH = glm::dot(L, H);
        return integrand(2.0 * LdotH * H - L) * 4.0 * LdotH * std::sin(t);
      };
      if (kinkElevations.empty())
      {
        return piecewise(f, breaks, 0.5 * (0.5 * kPi + delta), tolerance);
      }
      // N.V = r cos(2t - delta): it equals c at 2t = delta +- acos(c / r).
      const double r = std::hypot(sinI * cosPhi, cosI);
      std::vector<double> withKinks = breaks;
      for (double c : kinkElevations)
      {
        if (std::abs(c) < r)
        {
          const double a = std::acos(c / r);
          for (double t : { 0.5 * (delta - a), 0.5 * (delta + a) })
          {
            withKinks.insert(std::upper_bound(withKinks.begin(), withKinks.end(), t), t);
          }
        }
      }
      return piecewise(f, withKinks, 0.5 * (0.5 * kPi + delta), tolerance);
    }
    auto f = [&](double t) {
      const glm::dvec3 V = std::cos(t) * R + std::sin(t) * (cosPhi * T1 + sinPhi * T2);
      return integrand(V) * std::sin(t);
    };
    return piecewise(f, breaks, 0.5 * kPi + delta, tolerance);
  };

  // The integrand is even in the azimuth (mirror symmetry about the plane of
  // incidence, which holds the tangent X of the anisotropic models): twice
  // the integral over [0, pi]. A first pass sets the scale
  // of the tolerance.
  const double rough = 2.0 * adaptive([&](double phi) { return overAzimuth(phi, 1e-4); }, 0.0, kPi, 1e-2);
  const double tolerance = 1e-9 * std::max(1.0, std::abs(rough));
  auto outer = [&](double phi) { return overAzimuth(phi, 0.1 * tolerance); };
  return 2.0 * (adaptive(outer, 0.0, 0.5 * kPi, 0.25 * tolerance) + adaptive(outer, 0.5 * kPi, kPi, 0.25 * tolerance));
}

} // namespace shadelab
