#include "shadelab/CameraPlacement.h"

#include <algorithm>
#include <cmath>

namespace shadelab
{

namespace
{
constexpr double kPi = 3.14159265358979323846;

double radians(double degrees)
{
  return degrees * kPi / 180.0;
}

/// @p v turned by @p degrees about the unit @p axis (right-handed, Rodrigues).
glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& axis, double degrees)
{
  const double c = std::cos(radians(degrees)), s = std::sin(radians(degrees));
  return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0 - c);
}

/// @p up made unit and orthogonal to the unit view-plane normal @p n (which
/// points from the focal point to the eye), as vtkCamera::OrthogonalizeViewUp.
glm::dvec3 orthogonalUp(const glm::dvec3& up, const glm::dvec3& n)
{
  return glm::cross(n, glm::normalize(glm::cross(up, n)));
}

/// A unit view up that is not (almost) parallel to @p n: the scene's, or, as
/// vtkRenderer::ResetCamera substitutes, its components rotated.
glm::dvec3 usableUp(const glm::vec3& sceneUp, const glm::dvec3& n)
{
  glm::dvec3 up(sceneUp);
  const double length = glm::length(up);
  up = length > 0.0 && std::isfinite(length) ? up / length : glm::dvec3(0.0, 1.0, 0.0);
  if (std::abs(glm::dot(up, n)) > 0.999)
  {
    up = glm::dvec3(-up.z, up.x, up.y);
  }
  return up;
}
} // namespace

CameraView placeCamera(const SceneCamera& camera, const double bounds[6], int width, int height)
{
  glm::dvec3 low(-1.0), high(1.0);
  if (bounds && bounds[0] <= bounds[1] && bounds[2] <= bounds[3] && bounds[4] <= bounds[5])
  {
    low = glm::dvec3(bounds[0], bounds[2], bounds[4]);
    high = glm::dvec3(bounds[1], bounds[3], bounds[5]);
  }
  const glm::dvec3 centre = 0.5 * (low + high);
  double radius = 0.5 * glm::length(high - low);
  radius = radius > 0.0 ? radius : 0.5; // one point: vtkRenderer::ResetCamera's size

  CameraView view;
  view.viewAngle = camera.viewAngle;
  const double aspect = static_cast<double>(std::max(width, 1)) / std::max(height, 1);
  // Half the view angle across the narrower image direction.
  const double halfAngle = std::atan(std::tan(0.5 * radians(camera.viewAngle)) * std::min(1.0, aspect));
  view.parallelScale = radius / std::min(1.0, aspect);

  if (camera.hasPosition)
  {
    view.position = glm::dvec3(camera.position);
    view.focalPoint = glm::dvec3(camera.focalPoint);
    const glm::dvec3 n = glm::normalize(view.position - view.focalPoint);
    view.viewUp = orthogonalUp(usableUp(camera.viewUp, n), n);
  }
  else
  {
    const glm::dvec3 n0(0.0, 0.0, 1.0);
    const glm::dvec3 up = usableUp(camera.viewUp, n0);
    const double distance = radius / std::sin(halfAngle);
    glm::dvec3 offset = distance * n0;
    offset = rotate(offset, up, camera.azimuth);
    // vtkCamera::Elevation turns about minus the camera's sideways axis, and
    // its view transform (which OrthogonalizeViewUp reads) holds the view up
    // turned with it.
    const glm::dvec3 right = glm::normalize(glm::cross(up, glm::normalize(offset)));
    offset = rotate(offset, -right, camera.elevation);
    view.focalPoint = centre;
    view.position = centre + offset;
    view.viewUp = orthogonalUp(rotate(up, -right, camera.elevation), glm::normalize(offset));
  }

  // A clipping range holding the bounding sphere, with a margin.
  const glm::dvec3 direction = glm::normalize(view.focalPoint - view.position);
  const double depth = glm::dot(centre - view.position, direction);
  view.farPlane = std::max(depth + 1.01 * radius, 1e-3 * radius);
  view.nearPlane = std::max(depth - 1.01 * radius, 1e-3 * view.farPlane);
  return view;
}

} // namespace shadelab
