#ifndef slCornerWeights_h
#define slCornerWeights_h
/**
 * @file slCornerWeights.h
 * @brief How much a polygon corner adds to its vertex's normal, for the four
 * weightings. VTK-free. Geometry core (ShadeLab::GeometryCore).
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
 * edge weighs nothing, so it never brings a NaN; for Max weighting, neither
 * does a corner with edges so short that 1 / (|e1|² |e2|²) would overflow
 * (maxCornerWeight()).
 */

#include <glm/glm.hpp>

#include <cmath>
#include <limits>

namespace slnormals
{

enum class Weighting : int
{
  Uniform = 0,
  Area = 1,
  Angle = 2,
  Max = 3
};

/// atan(t) for t in [0, 1]: an odd minimax polynomial of degree 15,
/// |error| <= 3.8e-8 rad (fitted in double; in float, rounding (about 1e-7)
/// dominates). Evaluated in Estrin's scheme, t (c0 + c1 t^2 + ...) as
/// pairs combined by t^4 and t^8: a chain of 5 dependent multiply-adds
/// instead of Horner's 8, so that a vectorised loop over many corners is
/// not held up by one corner's chain.
template <typename T>
inline T atanUnit(T t)
{
  const T t2 = t * t;
  const T t4 = t2 * t2;
  const T t8 = t4 * t4;
  const T c01 = T(0.9999993355789613) + t2 * T(-0.3332986078429252);
  const T c23 = T(0.1994656563634464) + t2 * T(-0.13908629429161432);
  const T c45 = T(0.09642196935391509) + t2 * T(-0.055912320537255436);
  const T c67 = T(0.02186295306984301) + t2 * T(-0.004054565772727919);
  return t * ((c01 + t4 * c23) + t8 * (c45 + t4 * c67));
}

/// The angle in [0, pi] between two vectors from the length of their cross
/// product @p crossLength (>= 0) and their dot product @p dot: atan2(crossLength,
/// dot), and 0 when both are 0. Unlike acos(dot / (|e1| |e2|)) it needs no
/// square root per corner (a triangle's three corners share |e1 x e2|, twice
/// its area) and stays accurate near 0 and pi, where acos loses digits.
/// Selects only, no branch, so that loops over it vectorise. |error| <= 4e-8
/// rad in double, <= 4e-7 rad in float, against std::atan2
/// (GeometryCore.CornerAngleIsAtan2WithinItsDocumentedError).
template <typename T>
inline T cornerAngle(T crossLength, T dot)
{
  const T x = std::fabs(dot);
  const bool steep = crossLength > x;
  const T lo = steep ? x : crossLength;
  const T hi = steep ? crossLength : x;
  // hi is 0 only when lo is too; dividing by 1 then keeps the loop trap-free.
  const T r = atanUnit(lo / (hi > T(0) ? hi : T(1)));
  const T firstQuadrant = steep ? T(1.5707963267948966) - r : r;
  return dot < T(0) ? T(3.141592653589793) - firstQuadrant : firstQuadrant;
}

/// Max's weight sin θ / (|e1| |e2|) = @p crossLength / @p squaredLengths of a
/// corner whose edges e1, e2 have |e1 x e2| = @p crossLength and |e1|² |e2|²
/// = @p squaredLengths. A corner whose @p squaredLengths is below the smallest
/// normal T (about 1.2e-38 in float, 2.2e-308 in double: |e1| |e2| below
/// 1.1e-19 or 1.5e-154), where the quotient could overflow, weighs 0, as
/// one with a zero-length edge. So the weight is finite for every finite
/// input, and exact (up to rounding) for every other corner.
template <typename T>
inline T maxCornerWeight(T crossLength, T squaredLengths)
{
  return squaredLengths >= std::numeric_limits<T>::min() ? crossLength / squaredLengths : T(0);
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
      return unitNormal * cornerAngle(glm::length(glm::cross(e1, e2)), glm::dot(e1, e2));
    }
    case Weighting::Max:
    {
      const glm::vec<3, T> e1 = next - p;
      const glm::vec<3, T> e2 = prev - p;
      return unitNormal * maxCornerWeight(glm::length(glm::cross(e1, e2)), glm::dot(e1, e1) * glm::dot(e2, e2));
    }
  }
  return glm::vec<3, T>(0);
}

} // namespace slnormals

#endif
