#include "shadelab/Albedo.h"

#include <cmath>

namespace shadelab
{

double directionalAlbedo(int model, const glsl::slMaterial& material, double thetaI, int steps)
{
  const double pi = 3.14159265358979323846;
  const glm::vec3 N(0.0f, 0.0f, 1.0f);
  const glm::vec3 L(static_cast<float>(std::sin(thetaI)), 0.0f, static_cast<float>(std::cos(thetaI)));
  const double dTheta = 0.5 * pi / steps, dPhi = pi / steps;
  double sum = 0.0;
  for (int i = 0; i < steps; ++i)
  {
    const double thetaO = (i + 0.5) * dTheta;
    double ring = 0.0;
    for (int j = 0; j < 2 * steps; ++j)
    {
      const double phiO = (j + 0.5) * dPhi;
      const glm::vec3 V(static_cast<float>(std::sin(thetaO) * std::cos(phiO)),
        static_cast<float>(std::sin(thetaO) * std::sin(phiO)), static_cast<float>(std::cos(thetaO)));
      const glm::vec3 f = glsl::slBRDF(model, material, N, L, V);
      ring += (f.x + f.y + f.z) / 3.0;
    }
    sum += ring * std::cos(thetaO) * std::sin(thetaO);
  }
  return sum * dTheta * dPhi;
}

} // namespace shadelab
