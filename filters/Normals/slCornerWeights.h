#ifndef slCornerWeights_h
#define slCornerWeights_h
/**
 * @file slCornerWeights.h
 * @brief How much a polygon corner adds to its vertex's normal, for the four
 * weightings. VTK-free. Internal to ShadeLab::Normals.
 *
 * A vertex normal is the normalised sum, over the polygon corners at the
 * vertex, of weight × unit face normal:
 * - Uniform: 1 (what vtkPolyDataNormals does);
 * - Area: twice the polygon's area (the length of its Newell vector), as
 *   vtkTriangleMeshPointNormals;
 * - Angle (Thürmer & Wüthrich 1998): the corner's angle θ;
 * - Max (Nelson Max 1999): sin θ / (|e1| |e2|), the weight that is exact for
 *   vertices of a sphere, with e1, e2 the corner's two edges.
 *
 * A corner of a degenerate polygon (zero Newell vector) or with a zero-length
 * edge weighs nothing, so it never brings a NaN.
 */

#include <glm/glm.hpp>

#include <cmath>

namespace slnormals
{

enum class Weighting : int
{
  Uniform = 0,
  Area = 1,
  Angle = 2,
  Max = 3
};

/// acos(x) for x in [-1, 1], Abramowitz & Stegun 4.4.46 (|error| <= 2e-8 rad),
/// about four times faster than std::acos.
template <typename T>
inline T fastAcos(T x)
{
  const T a = std::fabs(x) < T(1) ? std::fabs(x) : T(1);
  const T p = T(1.5707963050) +
    a * (T(-0.2145988016) +
      a * (T(0.0889789874) +
        a * (T(-0.0501743046) +
          a * (T(0.0308918810) + a * (T(-0.0170881256) + a * (T(0.0066700901) + a * T(-0.0012624911)))))));
  const T r = std::sqrt(T(1) - a) * p;
  return x < T(0) ? T(3.14159265358979323846) - r : r;
}

/// The corner weight times the unit normal, for the corner at @p p whose
/// polygon continues to @p next and comes from @p prev. @p unitNormal is the
/// polygon's unit normal (zero for a degenerate polygon), @p doubleArea the
/// length of its Newell vector.
template <typename T>
inline glm::vec<3, T> cornerContribution(Weighting weighting, const glm::vec<3, T>& prev,
  const glm::vec<3, T>& p, const glm::vec<3, T>& next, const glm::vec<3, T>& unitNormal, T doubleArea)
{
  switch (weighting)
  {
    case Weighting::Uniform:
      return unitNormal;
    case Weighting::Area:
      return unitNormal * doubleArea;
    case Weighting::Angle:
    {
      const glm::vec<3, T> e1 = next - p;
      const glm::vec<3, T> e2 = prev - p;
      const T l = std::sqrt(glm::dot(e1, e1) * glm::dot(e2, e2));
      if (!(l > T(0)))
      {
        return glm::vec<3, T>(0);
      }
      return unitNormal * fastAcos(glm::dot(e1, e2) / l);
    }
    case Weighting::Max:
    {
      const glm::vec<3, T> e1 = next - p;
      const glm::vec<3, T> e2 = prev - p;
      const T l2 = glm::dot(e1, e1) * glm::dot(e2, e2);
      if (!(l2 > T(0)))
      {
        return glm::vec<3, T>(0);
      }
      // |e1 x e2| / (|e1|^2 |e2|^2) = sin(theta) / (|e1| |e2|)
      return unitNormal * (glm::length(glm::cross(e1, e2)) / l2);
    }
  }
  return glm::vec<3, T>(0);
}

} // namespace slnormals

#endif
