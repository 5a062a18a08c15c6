#ifndef shadelab_ValueLimits_h
#define shadelab_ValueLimits_h
/**
 * @file ValueLimits.h
 * @brief The largest values a scene may hold, named by the range columns of
 * LightingTables.h. Header only, no dependencies, so that the VTK classes'
 * public headers can clamp to them (MaterialParameters.h).
 *
 * Why upper limits on colours and intensities: every lighting term is a
 * product of intensity × light colour × material coefficient × a BRDF factor
 * (at most about n / 8π for the normalised models, n ≤ 1e5), summed over the
 * lights, in float. With each factor at most 1e6 the products stay below
 * 1e22, far from float's 3.4e38, so no finite scene can make a term infinite
 * (and infinity times a zero colour NaN). HDR lights and materials fit
 * easily.
 */

namespace shadelab
{

/// Largest colour component, light intensity, emission or background value.
constexpr double kMaxColourValue = 1e6;
/// Largest shininess n.
constexpr double kMaxShininess = 1e5;
/// Largest spot-light exponent.
constexpr double kMaxSpotExponent = 1e4;

} // namespace shadelab

#endif
