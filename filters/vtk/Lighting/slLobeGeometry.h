#ifndef slLobeGeometry_h
#define slLobeGeometry_h
/**
 * @file slLobeGeometry.h
 * @brief Internal: BRDF lobe surfaces and polar slices as polygons, shared
 * by slBRDFLobeSource and slLobesOnMesh. Not wrapped.
 *
 * The lobe for incident direction L at a surface with unit normal N is the
 * surface origin + scale r(w_o) w_o over the hemisphere of outgoing unit
 * directions w_o, with r = f_r(L, w_o) (slBRDF() of slLighting.glsl,
 * averaged over R, G, B), optionally times cos(theta_o). Tangent T lies in
 * the plane of incidence (the plane of N and L), on the side away from L;
 * with L along N it is the surface's tangent X (slTangentX()). B = N x T.
 *
 * f_r may instead be given per point (a BRDF that only the GPU evaluates,
 * a `.brdf` file): lobeDirections() and sliceDirections() list the outgoing
 * directions in the order the append functions make their points, and
 * the values come back in the same order.
 */

#include "shadelab/LightingGLSL.h"

#include <vector>

class vtkCellArray;
class vtkFloatArray;
class vtkPoints;

namespace shadelab
{

struct LobeSpec
{
  glsl::slMaterial material;
  int model = glsl::SL_MODEL_PHONG;
  glm::vec3 normal{ 0.0f, 0.0f, 1.0f };
  /// The surface's tangent X (anisotropic models; any length, see slTangentX()).
  glm::vec3 tangent{ 1.0f, 0.0f, 0.0f };
  glm::vec3 toLight{ 0.0f, 0.0f, 1.0f };
  bool timesCosine = false;
  int thetaResolution = 32; ///< rings from the normal to the horizon
  int phiResolution = 64;   ///< segments around the normal
  glm::vec3 origin{ 0.0f };
  /// Length per unit of r. A double: a lobe scaled to a visible size may
  /// have a largest r below float's smallest normal value (k_d = 1e-40).
  double scale = 1.0;
};

/// r(w_o) for one outgoing direction (0 below the horizon).
float lobeRadius(const LobeSpec& spec, const glm::vec3& out);

/// r from f_r = @p brdf at outgoing direction @p out: the mean of R, G, B,
/// times cos(theta_o) if spec.timesCosine; 0 where not finite.
float lobeRadiusFromBRDF(const LobeSpec& spec, const glm::vec3& brdf, const glm::vec3& out);

/// The outgoing unit directions of appendLobe()'s points, in their order.
std::vector<glm::vec3> lobeDirections(const LobeSpec& spec);

/// The outgoing unit directions of appendSlice()'s points, in their order.
std::vector<glm::vec3> sliceDirections(const LobeSpec& spec);

/// Appends the lobe surface (triangles) to @p points / @p polys, with r per
/// point in @p values; f_r from slBRDF(), or @p brdfValues (one per
/// direction of lobeDirections(spec)) when given.
void appendLobe(const LobeSpec& spec, vtkPoints* points, vtkCellArray* polys, vtkFloatArray* values,
  const std::vector<glm::vec3>* brdfValues = nullptr);

/// Appends the polar slice in the plane of incidence, theta_o from -90 to 90
/// degrees (positive on the side of the mirror direction), as one polyline;
/// f_r from slBRDF(), or @p brdfValues (one per direction of
/// sliceDirections(spec)) when given.
void appendSlice(const LobeSpec& spec, vtkPoints* points, vtkCellArray* lines, vtkFloatArray* values,
  const std::vector<glm::vec3>* brdfValues = nullptr);

} // namespace shadelab

#endif
