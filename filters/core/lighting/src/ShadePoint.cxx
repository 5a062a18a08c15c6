#include "shadelab/ShadePoint.h"

namespace shadelab
{

glsl::slTerms shadePoint(const std::vector<glsl::slLight>& lights, const glsl::slMaterial& material,
  int model, const glm::vec3& position, const glm::vec3& normal, const glm::vec3& eye,
  const glm::vec3& tangent)
{
  glsl::slTerms sum = glsl::slZeroTerms();
  for (const glsl::slLight& light : lights)
  {
    sum = glsl::slAddTerms(sum, glsl::slShadeLight(light, material, model, position, normal, tangent, eye));
  }
  return glsl::slAddEmission(sum, material);
}

} // namespace shadelab
