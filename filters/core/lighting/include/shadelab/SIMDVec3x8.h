#ifndef shadelab_SIMDVec3x8_h
#define shadelab_SIMDVec3x8_h
/**
 * @file SIMDVec3x8.h
 * @brief vec3x8 and bvec3x8: GLSL's vec3 and bvec3 for 8 points at a time,
 * structure of arrays (x, y, z are each a vfloat8), with the operators and
 * built-ins slLighting.glsl uses on vectors. See SIMDFloat8.h.
 */

#include "shadelab/SIMDFloat8.h"

#include <glm/vec3.hpp>

namespace shadelab
{
namespace simd
{

/// GLSL bvec3 for 8 lanes; bvec3x8(c) repeats one condition, as bvec3(c) does.
struct bvec3x8
{
  vmask8 x, y, z;
  explicit bvec3x8(vmask8 c)
    : x(c)
    , y(c)
    , z(c)
  {
  }
};

/// GLSL vec3 for 8 lanes.
struct vec3x8
{
  vfloat8 x, y, z;
  vec3x8() = default;
  /// vec3(s): every component s.
  explicit vec3x8(vfloat8 s)
    : x(s)
    , y(s)
    , z(s)
  {
  }
  vec3x8(vfloat8 a, vfloat8 b, vfloat8 c)
    : x(a)
    , y(b)
    , z(c)
  {
  }
  /// The same vector in every lane (a light's position, a material colour).
  vec3x8(const glm::vec3& v) // NOLINT: implicit, uniforms convert like literals
    : x(v.x)
    , y(v.y)
    , z(v.z)
  {
  }
};

inline vec3x8 operator+(const vec3x8& a, const vec3x8& b) { return { a.x + b.x, a.y + b.y, a.z + b.z }; }
inline vec3x8 operator-(const vec3x8& a, const vec3x8& b) { return { a.x - b.x, a.y - b.y, a.z - b.z }; }
inline vec3x8 operator*(const vec3x8& a, const vec3x8& b) { return { a.x * b.x, a.y * b.y, a.z * b.z }; }
inline vec3x8 operator-(const vec3x8& a) { return { -a.x, -a.y, -a.z }; }
inline vec3x8 operator*(vfloat8 s, const vec3x8& a) { return { s * a.x, s * a.y, s * a.z }; }
inline vec3x8 operator*(const vec3x8& a, vfloat8 s) { return { a.x * s, a.y * s, a.z * s }; }
inline vec3x8 operator/(const vec3x8& a, vfloat8 s) { return { a.x / s, a.y / s, a.z / s }; }

inline vfloat8 dot(const vec3x8& a, const vec3x8& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline vfloat8 length(const vec3x8& a) { return sqrt(dot(a, a)); }
inline vec3x8 normalize(const vec3x8& a) { return a / length(a); }

/// GLSL mix(a, b, bvec3 c): per component and lane, c ? b : a.
inline vec3x8 mix(const vec3x8& a, const vec3x8& b, const bvec3x8& c)
{
  return { mix(a.x, b.x, c.x), mix(a.y, b.y, c.y), mix(a.z, b.z, c.z) };
}

} // namespace simd
} // namespace shadelab

#endif
