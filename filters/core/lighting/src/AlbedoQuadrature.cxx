#include "shadelab/AlbedoQuadrature.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace shadelab
{

namespace
{
constexpr double kPi = 3.14159265358979323846;

/// The narrowest piece next to the mirror direction (radians).
constexpr double kFinestPiece = 0.01;

/// Gauss-Legendre nodes and weights on [-1, 1]: the roots of P_n by
/// Newton's method from Tricomi's estimate, weights 2 / ((1 - x^2) P_n'(x)^2).
struct GaussLegendre
{
  std::array<double, kAlbedoOrder> nodes{}, weights{};
  GaussLegendre()
  {
    const int n = kAlbedoOrder;
    for (int i = 0; i < n; ++i)
    {
      double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
      double derivative = 1.0;
      for (int iteration = 0; iteration < 100; ++iteration)
      {
        // P_n(x) and P_n'(x) by the three-term recurrence.
        double p0 = 1.0, p1 = x;
        for (int k = 2; k <= n; ++k)
        {
          const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        derivative = n * (x * p1 - p0) / (x * x - 1.0);
        const double step = p1 / derivative;
        x -= step;
        if (std::abs(step) < 1e-16)
        {
          break;
        }
      }
      nodes[static_cast<size_t>(i)] = x;
      weights[static_cast<size_t>(i)] = 2.0 / ((1.0 - x * x) * derivative * derivative);
    }
  }
};
} // namespace

namespace
{
/// Breaks of [lower, upper]: its ends, the @p points inside it, and
/// around each of @p peaks at -+ kFinestPiece 2^k, ascending.
std::vector<double> gradedBreaks(double lower, double upper, const std::vector<double>& peaks,
  const std::vector<double>& points = {})
{
  std::vector<double> breaks{ lower, upper };
  auto add = [&](double b) {
    if (b > lower && b < upper)
    {
      breaks.push_back(b);
    }
  };
  for (double peak : peaks)
  {
    add(peak);
    for (double d = kFinestPiece; d < upper - lower; d *= 2.0)
    {
      add(peak - d);
      add(peak + d);
    }
  }
  for (double point : points)
  {
    add(point);
  }
  std::sort(breaks.begin(), breaks.end());
  // Breaks closer than a tenth of the finest piece add nothing but nodes.
  std::vector<double> kept{ breaks.front() };
  for (double b : breaks)
  {
    if (b - kept.back() > 0.1 * kFinestPiece || b == breaks.back())
    {
      kept.push_back(b);
    }
  }
  if (kept.size() > 2 && kept[kept.size() - 1] - kept[kept.size() - 2] <= 0.1 * kFinestPiece)
  {
    kept.erase(kept.end() - 2);
  }
  return kept;
}

/// Gauss-Legendre nodes and weights over the pieces between @p breaks.
void compositeRule(const std::vector<double>& breaks, std::vector<double>& nodes, std::vector<double>& weights)
{
  static const GaussLegendre rule;
  for (size_t piece = 0; piece + 1 < breaks.size(); ++piece)
  {
    const double centre = 0.5 * (breaks[piece] + breaks[piece + 1]);
    const double half = 0.5 * (breaks[piece + 1] - breaks[piece]);
    for (int k = 0; k < kAlbedoOrder; ++k)
    {
      nodes.push_back(centre + half * rule.nodes[static_cast<size_t>(k)]);
      weights.push_back(half * rule.weights[static_cast<size_t>(k)]);
    }
  }
}
} // namespace

AlbedoQuadrature albedoQuadrature(const glm::dvec3& toLight)
{
  const glm::dvec3 L = glm::normalize(toLight);
  // The mirror direction R's spherical angles: theta_R = theta_i, phi_R
  // opposite the light's azimuth.
  const double thetaR = std::acos(std::clamp(L.z, -1.0, 1.0));
  const double phiR = std::atan2(-L.y, -L.x);
  std::vector<double> thetas, thetaWeights, phis, phiWeights;
  // theta: graded toward R and toward the horizon, where factors such as
  // Ward's 1 / sqrt(cos theta_o) make the integrand's slope unbounded.
  // phi: graded toward R, with breaks a right angle away (the kink of
  // Oren-Nayar's max(0, cos(phi_i - phi_o))).
  compositeRule(gradedBreaks(0.0, 0.5 * kPi, { thetaR, 0.5 * kPi }), thetas, thetaWeights);
  compositeRule(gradedBreaks(phiR - kPi, phiR + kPi, { phiR }, { phiR - 0.5 * kPi, phiR + 0.5 * kPi }), phis,
    phiWeights);

  AlbedoQuadrature out;
  for (size_t i = 0; i < thetas.size(); ++i)
  {
    const double sinT = std::sin(thetas[i]), cosT = std::cos(thetas[i]);
    for (size_t j = 0; j < phis.size(); ++j)
    {
      out.directions.emplace_back(sinT * std::cos(phis[j]), sinT * std::sin(phis[j]), cosT);
      // dw = sin(theta) dtheta dphi, times cos(theta_o).
      out.weights.push_back(thetaWeights[i] * phiWeights[j] * sinT * cosT);
    }
  }
  return out;
}

double albedoFromValues(const AlbedoQuadrature& rule, const std::vector<glm::vec3>& brdfValues)
{
  double sum = 0.0;
  for (size_t k = 0; k < rule.weights.size() && k < brdfValues.size(); ++k)
  {
    const glm::vec3& f = brdfValues[k];
    if (!std::isfinite(f.x) || !std::isfinite(f.y) || !std::isfinite(f.z))
    {
      return std::nan("");
    }
    sum += rule.weights[k] * (static_cast<double>(f.x) + f.y + f.z) / 3.0;
  }
  return sum;
}

} // namespace shadelab
