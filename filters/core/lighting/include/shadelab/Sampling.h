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
  glm::vec3 toWorld(const glm::vec3& local) const { return local.x * this->T + local.y * this->B + local.z * this->N; }
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

/// Veach's power heuristic (beta = 2) weight of a sample from density @p a
/// against another strategy's density @p b.
float powerHeuristic(float a, float b);

} // namespace shadelab

#endif
