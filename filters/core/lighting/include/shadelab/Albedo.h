#ifndef shadelab_Albedo_h
#define shadelab_Albedo_h
/**
 * @file Albedo.h
 * @brief Directional albedo a(theta_i) = integral over the hemisphere of
 * f_r(w_i, w_o) cos(theta_o) dw_o, with f_r from slBRDF() of slLighting.glsl
 * (mean of R, G, B), evaluated in double (LightingGLSLDouble.h).
 *
 * A physically plausible BRDF has a(theta_i) <= 1 for every theta_i. The
 * lecture models read literally are not: Lambert k_d cos theta gives pi k_d.
 *
 * The integral is taken in the lobe's own polar coordinates, where the
 * integrand is smooth and its peak sits at the pole: about the normal for
 * the diffuse models (split at theta_o = theta_i, Oren-Nayar's kink), about
 * the mirror direction R for the Phong models, about the normal in the space
 * of half vectors H for Blinn-Phong and the microfacet models (dw_o = 4 (L.H)
 * dw_h). For each azimuth the polar angle runs exactly to the horizon, so
 * the hemisphere's edge is an integration limit rather than a kink, and the
 * polar range is split at the lobe's width times 1, 2, 4, ... (and at
 * R.V = 0 for Phong, where max(0, R.V)^n has a kink; where N.V crosses the
 * kinks of Ashikhmin-Shirley and Beckmann in H, and at the step of
 * Ashikhmin-Shirley's exponent where 1 - (N.H)^2 reaches SL_MIN_COS_THETA).
 * The last piece is taken in
 * s = sqrt(t_horizon - t), smooth where Ward's integrand goes as a square
 * root of cos(theta_o). Each piece, and the azimuth, is integrated
 * by adaptive 15-point Gauss-Kronrod, bisecting until the Kronrod estimate
 * |K15 - G7| of each piece is below its share of 1e-9 max(1, |a|).
 */

#include "shadelab/LightingGLSL.h"

namespace shadelab
{

/// a(theta_i) for incidence @p thetaI (radians from the normal, 0 to just
/// below pi/2) under @p model (an SL_MODEL_* value, isLightingModel()) with
/// @p material.
double directionalAlbedo(int model, const glsl::slMaterial& material, double thetaI);

} // namespace shadelab

#endif
