#ifndef shadelab_Sampling_h
#define shadelab_Sampling_h
/**
 * @file Sampling.h
 * @brief Monte Carlo building blocks for the radiance-equation reference:
 * a small deterministic random generator, an orthonormal frame, direction
 * samplers with their densities (per unit solid angle) and the power
 * heuristic. The GPU never needs these, so they are plain C++ (no GLSL copy).
 *
 * Local directions have the frame's normal along +z; Frame::toWorld maps them.
 * The anisotropic samplers have the surface tangent X along +x and the
 * bitangent Y = N x X along +y (Frame(N, X)).
 *
 * The microfacet samplers draw a facet normal (half vector) H around +z; the
 * direction reflected about it is reflectAbout(V, H) and its density
 * reflectedPdf(). Each *Pdf function is the exact density of its sampler
 * (tests/core/SamplingTest.cxx checks histograms and integrals).
 */

#include <glm/glm.hpp>

#include <cstdint>

namespace shadelab
{

/// PCG32 (O'Neill 2014): tiny, fast, good enough for Monte Carlo, and
/// reproducible: one stream per (seed, point) gives the same numbers whatever
/// the thread schedule.
class Rng
{
public:
  Rng(std::uint64_t seed, std::uint64_t stream);
  std::uint32_t nextUInt();
  /// Uniform in [0, 1).
  float next();

private:
  std::uint64_t State = 0;
  std::uint64_t Increment = 1;
};

/// Orthonormal frame around a unit normal (Duff et al. 2017).
struct Frame
{
  explicit Frame(const glm::vec3& normal);
  /// The frame of unit normal @p normal and unit tangent @p tangent
  /// orthogonal to it: T = tangent, B = normal x tangent.
  Frame(const glm::vec3& normal, const glm::vec3& tangent);
  glm::vec3 toWorld(const glm::vec3& local) const { return local.x * this->T + local.y * this->B + local.z * this->N; }
  glm::vec3 toLocal(const glm::vec3& w) const
  {
    return glm::vec3(glm::dot(w, this->T), glm::dot(w, this->B), glm::dot(w, this->N));
  }
  glm::vec3 T, B, N;
};

/// Uniform on the hemisphere z >= 0: density 1 / (2 pi).
glm::vec3 sampleUniformHemisphere(float u1, float u2);
float uniformHemispherePdf();

/// Cosine-weighted on the hemisphere: density cos(theta) / pi.
glm::vec3 sampleCosineHemisphere(float u1, float u2);
float cosineHemispherePdf(float cosTheta);

/// Uniform in the cone of directions within acos(cosMax) of +z:
/// density 1 / (2 pi (1 - cosMax)).
glm::vec3 sampleUniformCone(float u1, float u2, float cosMax);
float uniformConePdf(float cosMax);

/// The normalised Phong lobe around +z: density (n + 1) / (2 pi) cos^n(alpha).
glm::vec3 samplePhongLobe(float u1, float u2, float n);
float phongLobePdf(float cosAlpha, float n);

/// GGX (Trowbridge-Reitz) facet normals of width @p alpha visible from the
/// unit direction @p V (V.z > 0), by Heitz's (2018) "Sampling the GGX
/// distribution of visible normals": density G1(V) max(0, V.H) D(H) / V.z per
/// unit solid angle of H, with D slGGXDistribution() and Smith's
/// G1(V) = 2 V.z / (V.z + sqrt(alpha^2 (1 - V.z^2) + V.z^2)).
glm::vec3 sampleGGXVisibleNormal(const glm::vec3& V, float alpha, float u1, float u2);
float ggxVisibleNormalPdf(const glm::vec3& V, const glm::vec3& H, float alpha);

/// Beckmann facet normals of width @p alpha in proportion to D(H) cos(theta_h)
/// (Walter et al. 2007, eqs. 28-29): tan^2(theta_h) = -alpha^2 ln(1 - u1);
/// density slBeckmannDistribution() times H.z.
glm::vec3 sampleBeckmannNormal(float alpha, float u1, float u2);
float beckmannNormalPdf(const glm::vec3& H, float alpha);

/// Ward's anisotropic Gaussian of facet slopes, widths @p ax along +x and
/// @p ay along +y (Walter 2005, "Notes on the Ward BRDF"): phi_h =
/// atan(ay/ax tan(2 pi u2)) in u2's quadrant, tan^2(theta_h) = -ln(1 - u1) /
/// (cos^2 phi_h / ax^2 + sin^2 phi_h / ay^2); density
/// exp(-tan^2(theta_h) (cos^2 phi_h / ax^2 + sin^2 phi_h / ay^2)) / (pi ax ay cos^3 theta_h).
glm::vec3 sampleWardNormal(float ax, float ay, float u1, float u2);
float wardNormalPdf(const glm::vec3& H, float ax, float ay);

/// Ashikhmin and Shirley's (2000) anisotropic power of N.H, exponents @p nu
/// along +x and @p nv along +y: phi_h = atan(sqrt((nu + 1) / (nv + 1))
/// tan(2 pi u2)) in u2's quadrant, cos(theta_h) = (1 - u1)^(1 / (e + 1)),
/// e = nu cos^2 phi_h + nv sin^2 phi_h; density sqrt((nu + 1) (nv + 1)) / (2 pi) H.z^e.
glm::vec3 sampleAshikhminShirleyNormal(float nu, float nv, float u1, float u2);
float ashikhminShirleyNormalPdf(const glm::vec3& H, float nu, float nv);

/// The reflection of unit @p V about unit @p H: 2 (V.H) H - V.
glm::vec3 reflectAbout(const glm::vec3& V, const glm::vec3& H);
/// The density of reflectAbout(V, H) at @p L when H has density @p pdfH at
/// H = +-(L + V) / |L + V| (the sign that puts H above the surface, which
/// the caller chose): pdfH / (4 |V.H|); 0 where L = -V.
float reflectedPdf(float pdfH, const glm::vec3& V, const glm::vec3& H);

/// Veach's power heuristic (beta = 2) weight of a sample from density @p a
/// against another strategy's density @p b.
float powerHeuristic(float a, float b);

} // namespace shadelab

#endif
