#ifndef shadelab_RadianceEstimator_h
#define shadelab_RadianceEstimator_h
/**
 * @file RadianceEstimator.h
 * @brief Monte Carlo estimate, at one surface point, of the radiance
 * equation L_o = L_e + integral over the hemisphere of f_r L_i cos(theta) dw,
 * with f_r from slBRDF() of slLighting.glsl.
 *
 * Incident light L_i: an environment map (EnvironmentMap) and/or the scene's
 * lights as small spherical area lights. A point or spot light of radius r
 * at distance d subtends the cone sin(alpha) = r / d; a directional light a
 * cone of the given angular radius. Each cone has uniform radiance chosen so
 * that its irradiance at normal incidence equals what the discrete light
 * delivers (I x reach: attenuation and spot factor of slLightReach(), light
 * colour = its diffuse colour): L = I reach / (pi sin^2 alpha). As the cone
 * shrinks the estimate tends to the discrete formula, so reference minus
 * discrete isolates what the point-light approximation leaves out.
 * No shadows or interreflection (local lighting), no ambient term.
 *
 * Strategies: uniform and cosine-weighted hemisphere sampling, BRDF
 * importance sampling (BRDFSampler.h: a mixture of the cosine lobe for k_d
 * and the model's own specular lobe for k_s: Phong, Blinn-Phong, GGX's
 * visible normals, Beckmann, Ward, Ashikhmin-Shirley), light sampling (the environment map's own
 * importance sampling plus uniform cone sampling of the lights) and
 * multiple importance sampling (one BRDF and one light sample per iteration,
 * power heuristic).
 */

#include "shadelab/EnvironmentMap.h"
#include "shadelab/LightingGLSL.h"

#include <cstdint>
#include <vector>

namespace shadelab
{

enum class SamplingStrategy
{
  Uniform = 0,
  Cosine = 1,
  BRDF = 2,
  Light = 3,
  MIS = 4
};

struct ReferenceSetup
{
  std::vector<glsl::slLight> lights; ///< world space; ambient lights are ignored
  bool useLights = true;
  float lightRadius = 0.05f;           ///< world units, point and spot lights
  float directionalAngularRadius = 0.01f; ///< radians
  const EnvironmentMap* environment = nullptr; ///< null or empty: none
  float environmentScale = 1.0f;
  glsl::slMaterial material;
  int model = glsl::SL_MODEL_LAMBERT_NORMALIZED; ///< an SL_MODEL_* value (isLightingModel())
  SamplingStrategy strategy = SamplingStrategy::MIS;
  int samples = 64;
  std::uint64_t seed = 1;
};

struct RadianceEstimate
{
  glm::vec3 mean{ 0.0f };     ///< includes the emission k_e
  glm::vec3 stdError{ 0.0f }; ///< standard error of the mean
};

/// The estimate at @p P (normal @p N, any length; tangent @p T, any length,
/// read by the anisotropic models only) seen from @p eye; @p stream
/// (e.g. the point id) selects the random stream, so results do not depend on
/// the order points are processed in. A zero normal gives emission only.
RadianceEstimate estimateRadiance(
  const ReferenceSetup& setup, const glm::vec3& P, const glm::vec3& N, const glm::vec3& T, const glm::vec3& eye,
  std::uint64_t stream);

} // namespace shadelab

#endif
