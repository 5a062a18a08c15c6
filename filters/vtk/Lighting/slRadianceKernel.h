#ifndef slRadianceKernel_h
#define slRadianceKernel_h
/**
 * @file slRadianceKernel.h
 * @brief Internal: the per-point lighting loop of slRadianceFilter, in a
 * vectorisable form. Not wrapped.
 *
 * It evaluates slShadeLightUnit() of slLighting.glsl (slShadeLight() with
 * the normal and view direction normalised once per point) through
 * shadelab/LightingGLSLBatch.h, the same file compiled for 8 points at a time
 * on SIMD batch types: each batch of 8 points goes through every light while
 * the sums stay in registers, with the lighting model and each light's type
 * fixed at compile time. Results agree with shadelab::glsl to about 1e-5
 * relative (pow and exp2 are polynomials there, see SIMDFloat8.h).
 */

#include "shadelab/LightingGLSL.h"
#include "shadelab/LightingTables.h"

#include <vector>

namespace shadelab
{

struct RadianceKernelInput
{
  const float* points = nullptr;  ///< xyz per point
  const float* normals = nullptr; ///< xyz per point, any length
  /// xyz per point, any length: the surface's tangent X, read by the
  /// anisotropic models only (modelNeedsTangents()); null: none (slTangentX()).
  const float* tangents = nullptr;
  /// Optional base colour per point (rgb): it multiplies the material's k_a
  /// and k_d there, as scalar colours and textures do in slLightingPass.
  const float* baseColour = nullptr;
  std::vector<glsl::slLight> lights;
  glsl::slMaterial material;
  ShadingModel model = ShadingModel::Lambert;
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

/// Shades points [begin, end). The model and every light's type must be rows
/// of LightingTables.h (sceneValueProblem() checks a scene's); points are
/// left unwritten otherwise. Returns the first of them whose normal has no
/// direction (zero-length or not finite: slSafeNormalize gives the zero
/// vector, and the point gets no diffuse or specular light), or @p end.
long long shadeRange(const RadianceKernelInput& in, const RadianceKernelOutput& out, long long begin, long long end);

} // namespace shadelab

#endif
