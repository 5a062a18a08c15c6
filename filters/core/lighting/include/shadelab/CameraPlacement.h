#ifndef shadelab_CameraPlacement_h
#define shadelab_CameraPlacement_h
/**
 * @file CameraPlacement.h
 * @brief The one rule that turns a scene's camera into a view: where the eye
 * is, what it looks at and which way is up, for a given mesh and image size.
 *
 * Every renderer and every CPU lighting filter goes through this function
 * (via slScene::ApplyCamera), so camera-space lights, the eye of specular
 * terms and the drawn picture all come from the same view.
 *
 * A camera with a position keeps it. A camera without one is fitted: it looks
 * at the centre of the bounds down -z from the distance at which the bounding
 * sphere fills the narrower image direction (the vertical view angle, or the
 * horizontal one it implies for a portrait image), as vtkRenderer::ResetCamera
 * does; then it turns by `azimuth` about the view up through the centre and by
 * `elevation` about the camera's right axis, as vtkCamera::Azimuth() and
 * vtkCamera::Elevation() do. Turning about the centre keeps the bounding sphere
 * in view, so every point of the bounds projects inside the image for every
 * aspect ratio and angle.
 */

#include "shadelab/Scene.h"

#include <glm/glm.hpp>

namespace shadelab
{

struct CameraView
{
  glm::dvec3 position{ 0.0, 0.0, 1.0 };
  glm::dvec3 focalPoint{ 0.0 };
  glm::dvec3 viewUp{ 0.0, 1.0, 0.0 }; ///< unit, orthogonal to the view direction
  double viewAngle = 30.0;            ///< vertical, degrees
  double parallelScale = 1.0;         ///< half the image height for a parallel projection
  double nearPlane = 0.01;            ///< a clipping range that holds the bounds
  double farPlane = 1000.0;
};

/// The view of @p camera for an image of @p width x @p height pixels showing
/// the box @p bounds (xmin, xmax, ymin, ymax, zmin, zmax). The bounds are an
/// input, not computed here, so that a caller holding only part of the mesh
/// (one MPI rank) can pass the bounds of the whole. Bounds with min > max
/// (nothing to show) count as the unit sphere about the origin; sizes below 1
/// count as 1.
CameraView placeCamera(const SceneCamera& camera, const double bounds[6], int width, int height);

} // namespace shadelab

#endif
