#ifndef shadelab_AlbedoQuadrature_h
#define shadelab_AlbedoQuadrature_h
/**
 * @file AlbedoQuadrature.h
 * @brief A fixed quadrature for the directional albedo
 * a(w_i) = integral over the hemisphere of f_r(w_i, w_o) cos(theta_o) dw_o
 * of a BRDF known only at chosen directions (a `.brdf` file's GLSL, which
 * runs on the GPU): the nodes w_o to evaluate f_r at, and their weights.
 *
 * The rule: spherical coordinates (theta_o, phi_o) about N, so the
 * horizon is the fixed limit theta_o = pi/2, where the integrand goes to 0;
 * theta_o is split at the mirror direction R's angle and at the horizon
 * +- 0.01 x 2^k (k = 0, 1, ...), phi_o at R's azimuth +- 0.01 x 2^k and at
 * a right angle from it, so the pieces are smallest where specular lobes
 * peak, where factors like Ward's 1 / sqrt(cos theta_o) have unbounded
 * slopes and where Oren-Nayar's max(0, cos(phi_i - phi_o)) has a kink; each
 * piece takes kAlbedoOrder-point Gauss-Legendre (product rule). No symmetry
 * is assumed: anisotropic BRDFs are integrated as they are.
 *
 * Accuracy (tests/core/AlbedoQuadratureTest.cxx, against
 * directionalAlbedo() at incidences 0 to 89 degrees): the rule itself (f_r
 * in double) is within 1e-8 for normalised Phong and Blinn-Phong (k_d =
 * 0.3, k_s = 0.7) at n = 50 and n = 1000 and within 2e-6 at n = 10^4, and
 * within 1e-7 relative for every built-in model with the scene format's
 * default roughness (GGX, Beckmann, Oren-Nayar, Ward, Ashikhmin-Shirley).
 * With f_r and the nodes in float, as on the GPU, the differences are
 * below 1e-6 at n = 50, 2e-5 at n = 1000 and 3e-4 at n = 10^4 (float
 * rounding of N.H raised to the n-th power). About 34,000 nodes.
 */

#include <glm/vec3.hpp>

#include <vector>

namespace shadelab
{

/// Gauss-Legendre points per piece of each coordinate.
constexpr int kAlbedoOrder = 8;

/// Nodes (unit outgoing directions, N = +z; a GPU takes them as float) and weights: the albedo is the
/// sum over k of weights[k] f_r(w_i, directions[k]) (cos(theta_o) and the
/// measure are in the weights).
struct AlbedoQuadrature
{
  std::vector<glm::dvec3> directions;
  std::vector<double> weights;
};

/// The rule for the unit direction toward the light @p toLight (z > 0).
AlbedoQuadrature albedoQuadrature(const glm::dvec3& toLight);

/// The albedo from f_r at the rule's nodes (RGB, mean of the three), or
/// NaN if a value is not finite.
double albedoFromValues(const AlbedoQuadrature& rule, const std::vector<glm::vec3>& brdfValues);

} // namespace shadelab

#endif
