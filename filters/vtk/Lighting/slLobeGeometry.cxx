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
    // Light along the normal: no plane of incidence. The surface's tangent X
    // takes its place, the limit of the planes of incidence as the light
    // leaves the normal on the -X side (slBRDFLobeSource's x-z plane), so the
    // slice of an anisotropic lobe shows roughnessX at every incidence.
    T = glsl::slTangentX(N, spec.tangent);
  }
  B = glm::cross(N, T);
}

/// Adds the points of @p directions with r from @p brdfValues or slBRDF();
/// returns the id of the first.
vtkIdType addPoints(const LobeSpec& spec, const std::vector<glm::vec3>& directions,
  const std::vector<glm::vec3>* brdfValues, vtkPoints* points, vtkFloatArray* values)
{
  const vtkIdType first = points->GetNumberOfPoints();
  for (size_t k = 0; k < directions.size(); ++k)
  {
    const glm::vec3& w = directions[k];
    const float r = brdfValues ? lobeRadiusFromBRDF(spec, (*brdfValues)[k], w) : lobeRadius(spec, w);
    const glm::dvec3 p = glm::dvec3(spec.origin) + (spec.scale * r) * glm::dvec3(w);
    values->InsertNextValue(r);
    points->InsertNextPoint(p.x, p.y, p.z);
  }
  return first;
}

int ringsOf(const LobeSpec& spec)
{
  return std::max(1, spec.thetaResolution);
}

int segmentsOf(const LobeSpec& spec)
{
  return std::max(3, spec.phiResolution);
}
} // namespace

float lobeRadius(const LobeSpec& spec, const glm::vec3& out)
{
  const glm::vec3 N = glsl::slSafeNormalize(spec.normal);
  const glm::vec3 L = glsl::slSafeNormalize(spec.toLight);
  return lobeRadiusFromBRDF(spec, glsl::slBRDF(spec.model, spec.material, N, spec.tangent, L, out), out);
}

float lobeRadiusFromBRDF(const LobeSpec& spec, const glm::vec3& f, const glm::vec3& out)
{
  float r = (f.x + f.y + f.z) / 3.0f;
  if (spec.timesCosine)
  {
    r *= std::max(glm::dot(glsl::slSafeNormalize(spec.normal), out), 0.0f);
  }
  return std::isfinite(r) ? r : 0.0f;
}

std::vector<glm::vec3> lobeDirections(const LobeSpec& spec)
{
  glm::vec3 N, T, B;
  frame(spec, N, T, B);
  const int rings = ringsOf(spec), segments = segmentsOf(spec);
  const float pi = glsl::SL_PI;
  std::vector<glm::vec3> directions{ N };
  for (int i = 1; i <= rings; ++i)
  {
    const float theta = 0.5f * pi * i / rings;
    for (int j = 0; j < segments; ++j)
    {
      const float phi = 2.0f * pi * j / segments;
      directions.push_back(std::sin(theta) * (std::cos(phi) * T + std::sin(phi) * B) + std::cos(theta) * N);
    }
  }
  return directions;
}

std::vector<glm::vec3> sliceDirections(const LobeSpec& spec)
{
  glm::vec3 N, T, B;
  frame(spec, N, T, B);
  const int steps = 2 * ringsOf(spec) * 4;
  std::vector<glm::vec3> directions;
  for (int i = 0; i <= steps; ++i)
  {
    const float theta = glsl::SL_PI * (static_cast<float>(i) / steps - 0.5f);
    directions.push_back(std::sin(theta) * T + std::cos(theta) * N);
  }
  return directions;
}

void appendLobe(const LobeSpec& spec, vtkPoints* points, vtkCellArray* polys, vtkFloatArray* values,
  const std::vector<glm::vec3>* brdfValues)
{
  const int rings = ringsOf(spec), segments = segmentsOf(spec);
  const vtkIdType pole = addPoints(spec, lobeDirections(spec), brdfValues, points, values);
  // Point j of ring i (1-based) follows the pole ring by ring.
  auto id = [&](int i, int j) { return pole + 1 + static_cast<vtkIdType>(i - 1) * segments + j % segments; };
  for (int i = 1; i <= rings; ++i)
  {
    for (int j = 0; j < segments; ++j)
    {
      if (i == 1)
      {
        const vtkIdType tri[3] = { pole, id(i, j), id(i, j + 1) };
        polys->InsertNextCell(3, tri);
        continue;
      }
      const vtkIdType t1[3] = { id(i - 1, j), id(i, j), id(i, j + 1) };
      const vtkIdType t2[3] = { id(i - 1, j), id(i, j + 1), id(i - 1, j + 1) };
      polys->InsertNextCell(3, t1);
      polys->InsertNextCell(3, t2);
    }
  }
}

void appendSlice(const LobeSpec& spec, vtkPoints* points, vtkCellArray* lines, vtkFloatArray* values,
  const std::vector<glm::vec3>* brdfValues)
{
  const std::vector<glm::vec3> directions = sliceDirections(spec);
  const vtkIdType first = addPoints(spec, directions, brdfValues, points, values);
  std::vector<vtkIdType> ids(directions.size());
  for (size_t k = 0; k < ids.size(); ++k)
  {
    ids[k] = first + static_cast<vtkIdType>(k);
  }
  lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
}

} // namespace shadelab
