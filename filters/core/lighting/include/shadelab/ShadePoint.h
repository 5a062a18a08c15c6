#ifndef shadelab_ShadePoint_h
#define shadelab_ShadePoint_h
/**
 * @file ShadePoint.h
 * @brief The whole lighting equation at one surface point, on the CPU.
 *
 * A thin loop over slShadeLight() from slLighting.glsl: the formulas live
 * there only.
 */

#include "shadelab/LightingGLSL.h"

#include <vector>

namespace shadelab
{

/// Ambient, diffuse, specular and emission at @p position with normal
/// @p normal (any length) and tangent @p tangent (any length; read by the
/// anisotropic models only, see slTangentX()) seen from @p eye, summed over
/// @p lights (world space, see toEvaluationLight()). @p model is an
/// SL_MODEL_* value.
/// The total is glsl::slTotal() of the result. Always finite for finite input.
glsl::slTerms shadePoint(const std::vector<glsl::slLight>& lights, const glsl::slMaterial& material,
  int model, const glm::vec3& position, const glm::vec3& normal, const glm::vec3& eye,
  const glm::vec3& tangent = glm::vec3(0.0f));

} // namespace shadelab

#endif
