#include "slLobeGeometry.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPoints.h>

#include <cmath>
#include <vector>

namespace shadelab
{

namespace
{
/// Unit T in the plane of incidence (toward the mirror side), B = N x T.
void frame(const LobeSpec& spec, glm::vec3& N, glm::vec3& T, glm::vec3& B)
{
  N = glsl::slSafeNormalize(spec.normal);
  const glm::vec3 L = glsl::slSafeNormalize(spec.toLight);
  // Mirror side: away from the light's tangential component.
  T = glsl::slSafeNormalize(glm::dot(N, L) * N - L);
  if (glm::length(T) == 0.0f)
  {
    const glm::vec3 helper = std::abs(N.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    T = glsl::slSafeNormalize(glm::cross(helper, N));
  }
  B = glm::cross(N, T);
}

vtkIdType addPoint(const LobeSpec& spec, const glm::vec3& direction, vtkPoints* points, vtkFloatArray* values)
{
  const float r = lobeRadius(spec, direction);
  const glm::dvec3 p = glm::dvec3(spec.origin) + (spec.scale * r) * glm::dvec3(direction);
  values->InsertNextValue(r);
  return points->InsertNextPoint(p.x, p.y, p.z);
}
} // namespace

float lobeRadius(const LobeSpec& spec, const glm::vec3& out)
{
  const glm::vec3 N = glsl::slSafeNormalize(spec.normal);
  const glm::vec3 L = glsl::slSafeNormalize(spec.toLight);
  const glm::vec3 f = glsl::slBRDF(spec.model, spec.material, N, L, out);
  float r = (f.x + f.y + f.z) / 3.0f;
  if (spec.timesCosine)
  {
    r *= std::max(glm::dot(N, out), 0.0f);
  }
  return std::isfinite(r) ? r : 0.0f;
}

void appendLobe(const LobeSpec& spec, vtkPoints* points, vtkCellArray* polys, vtkFloatArray* values)
{
  glm::vec3 N, T, B;
  frame(spec, N, T, B);
  const int rings = std::max(1, spec.thetaResolution), segments = std::max(3, spec.phiResolution);
  const float pi = glsl::SL_PI;
  const vtkIdType pole = addPoint(spec, N, points, values);
  std::vector<vtkIdType> previous(static_cast<size_t>(segments), pole), current(static_cast<size_t>(segments));
  for (int i = 1; i <= rings; ++i)
  {
    const float theta = 0.5f * pi * i / rings;
    for (int j = 0; j < segments; ++j)
    {
      const float phi = 2.0f * pi * j / segments;
      const glm::vec3 w = std::sin(theta) * (std::cos(phi) * T + std::sin(phi) * B) + std::cos(theta) * N;
      current[static_cast<size_t>(j)] = addPoint(spec, w, points, values);
    }
    for (int j = 0; j < segments; ++j)
    {
      const size_t a = static_cast<size_t>(j), b = static_cast<size_t>((j + 1) % segments);
      if (i == 1)
      {
        const vtkIdType tri[3] = { pole, current[a], current[b] };
        polys->InsertNextCell(3, tri);
        continue;
      }
      const vtkIdType t1[3] = { previous[a], current[a], current[b] };
      const vtkIdType t2[3] = { previous[a], current[b], previous[b] };
      polys->InsertNextCell(3, t1);
      polys->InsertNextCell(3, t2);
    }
    previous = current;
  }
}

void appendSlice(const LobeSpec& spec, vtkPoints* points, vtkCellArray* lines, vtkFloatArray* values)
{
  glm::vec3 N, T, B;
  frame(spec, N, T, B);
  const int steps = 2 * std::max(1, spec.thetaResolution) * 4;
  std::vector<vtkIdType> ids;
  for (int i = 0; i <= steps; ++i)
  {
    const float theta = glsl::SL_PI * (static_cast<float>(i) / steps - 0.5f);
    ids.push_back(addPoint(spec, std::sin(theta) * T + std::cos(theta) * N, points, values));
  }
  lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
}

} // namespace shadelab
