#ifndef slRadianceKernel_h
#define slRadianceKernel_h
/**
 * @file slRadianceKernel.h
 * @brief Internal: the per-point lighting loop of slRadianceFilter, in a
 * vectorisable form. Not wrapped.
 *
 * It evaluates slShadeLightUnit() of slLighting.glsl (slShadeLight() with
 * the normal and view direction normalised once per point) through
 * shadelab/LightingGLSLVectorizable.h, for blocks of points, light by light,
 * with the lighting model and each light's type fixed at compile time so that
 * GCC vectorises the loop over points (AVX2 + FMA where the CPU has them,
 * chosen at run time). Results agree with shadelab::glsl to about 1e-5
 * relative (the pow built-in differs, see LightingGLSLVectorizable.h).
 */

#include "shadelab/LightingGLSL.h"

#include <vector>

namespace shadelab
{

struct RadianceKernelInput
{
  const float* points = nullptr;  ///< xyz per point
  const float* normals = nullptr; ///< xyz per point, any length
  const float* diffuse = nullptr; ///< optional k_d per point (rgb), else the material's
  std::vector<glsl::slLight> lights;
  glsl::slMaterial material;
  int model = 0;
  glm::vec3 eye{ 0.0f };
};

/// Output arrays, rgb per point; perLight may be empty or hold one array per light.
struct RadianceKernelOutput
{
  float* ambient = nullptr;
  float* diffuse = nullptr;
  float* specular = nullptr;
  float* emission = nullptr;
  float* radiance = nullptr;
  std::vector<float*> perLight;
};

/// Shades points [begin, end).
void shadeRange(const RadianceKernelInput& in, const RadianceKernelOutput& out, long long begin, long long end);

} // namespace shadelab

#endif
