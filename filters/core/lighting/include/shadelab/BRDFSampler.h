#ifndef shadelab_BRDFSampler_h
#define shadelab_BRDFSampler_h
/**
 * @file BRDFSampler.h
 * @brief Importance sampling of the incident direction L in proportion to
 * (roughly) slBRDF(model, m, N, T, L, V) cos(theta_L) at one surface point,
 * with the sampler's exact density: the BRDF strategy of the radiance
 * reference (RadianceEstimator.h).
 *
 * A mixture of two strategies, chosen with probability k_d / (k_d + k_s)
 * (means over R, G, B; k_s counts only for a model with a specular term):
 *   - k_d: the cosine-weighted hemisphere (Lambert, Oren-Nayar and every
 *     diffuse term);
 *   - k_s, by the model's SpecularLobe: the normalised Phong lobe around the
 *     mirror direction R (Phong), its power of N.H (Blinn-Phong), GGX's
 *     visible normals (Heitz 2018), Beckmann's D(H) cos(theta_h) (Walter et
 *     al. 2007), Ward's anisotropic Gaussian (Walter 2005) or Ashikhmin and
 *     Shirley's anisotropic power of N.H, each reflecting V about the facet
 *     normal H drawn (dw_L = 4 |V.H| dw_h).
 * The microfacet lobes use the formulas' roughness floor SL_MIN_ROUGHNESS;
 * they reflect nothing where N.V <= 0, so there only k_d is sampled.
 */

#include "shadelab/LightingGLSL.h"
#include "shadelab/LightingTables.h"
#include "shadelab/Sampling.h"

namespace shadelab
{

class BRDFSampler
{
public:
  /// The sampler at a point of unit normal @p N, tangent @p T (any length:
  /// the anisotropic models' X is slTangentX(N, T)) and unit direction @p V
  /// toward the eye, for @p model (an SL_MODEL_* value, isLightingModel())
  /// and @p material.
  BRDFSampler(int model, const glsl::slMaterial& material, const glm::vec3& N, const glm::vec3& T, const glm::vec3& V);

  /// A unit direction L from three uniform numbers in [0, 1): @p choice picks
  /// the strategy, @p u1 and @p u2 the direction. L may lie below the surface
  /// (where the BRDF is 0).
  glm::vec3 sample(float choice, float u1, float u2) const;

  /// The density of sample() per unit solid angle at unit @p L, anywhere on
  /// the sphere.
  float pdf(const glm::vec3& L) const;

  /// The probability of the cosine (k_d) strategy.
  float diffuseWeight() const { return this->DiffuseWeight; }

private:
  /// The density of the specular strategy's facet normal H (local frame).
  float halfwayPdf(const glm::vec3& H) const;

  SpecularLobe Lobe = SpecularLobe::None;
  Frame Local;          ///< +z the normal, +x the tangent X
  glm::vec3 V;          ///< toward the eye, local
  glm::vec3 Mirror;     ///< R = 2 (N.V) N - V, local (Phong)
  float DiffuseWeight = 1.0f;
  float Power = 0.0f;   ///< Phong, Blinn-Phong: the shininess n
  float AlphaX = 1.0f;  ///< the roughness along X (or the only one)
  float AlphaY = 1.0f;  ///< along Y
};

} // namespace shadelab

#endif
