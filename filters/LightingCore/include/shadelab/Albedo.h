#ifndef shadelab_Albedo_h
#define shadelab_Albedo_h
/**
 * @file Albedo.h
 * @brief Directional albedo a(theta_i) = integral over the hemisphere of
 * f_r(w_i, w_o) cos(theta_o) dw_o, by the midpoint rule, with f_r from
 * slBRDF() of slLighting.glsl (mean of R, G, B).
 *
 * A physically plausible BRDF has a(theta_i) <= 1 for every theta_i. The
 * lecture models read literally are not: Lambert k_d cos theta gives pi k_d.
 */

#include "shadelab/LightingGLSL.h"

namespace shadelab
{

/// a(theta_i) for incidence @p thetaI (radians from the normal) with
/// @p steps midpoint rings in theta_o and 2 * steps segments in phi_o.
double directionalAlbedo(int model, const glsl::slMaterial& material, double thetaI, int steps = 128);

} // namespace shadelab

#endif
