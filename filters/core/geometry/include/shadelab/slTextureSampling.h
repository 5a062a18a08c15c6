#ifndef slTextureSampling_h
#define slTextureSampling_h
/**
 * @file slTextureSampling.h
 * @brief A texture in memory and its bilinear sampling, plus the tangent-space
 * normal of bump mapping. VTK-free. Geometry core (ShadeLab::GeometryCore). (How a
 * tangent-space normal reaches the surface is glsl/slNormalMapping.glsl,
 * shared with the render pass.)
 *
 * Texel (i, j) covers u in [i/W, (i+1)/W], v in [j/H, (j+1)/H], row 0 at the
 * bottom (v = 0), its value sits at its centre, and coordinates wrap around
 * (repeat), as OpenGL's GL_REPEAT with GL_LINEAR.
 */

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

namespace slnormals
{

struct Texture
{
  int width = 0, height = 0, channels = 0;
  std::vector<float> texels; ///< width * height * channels, rows bottom-up, values as stored (0..1 for 8-bit)

  float texel(int i, int j, int c) const
  {
    i = ((i % this->width) + this->width) % this->width;
    j = ((j % this->height) + this->height) % this->height;
    return this->texels[(static_cast<size_t>(j) * this->width + i) * this->channels + c];
  }

  /// Bilinear value of channel @p c at (u, v).
  float sample(double u, double v, int c) const
  {
    const double x = u * this->width - 0.5, y = v * this->height - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const int i = static_cast<int>(fx), j = static_cast<int>(fy);
    const double a = x - fx, b = y - fy;
    return static_cast<float>((1 - a) * (1 - b) * this->texel(i, j, c) + a * (1 - b) * this->texel(i + 1, j, c) +
      (1 - a) * b * this->texel(i, j + 1, c) + a * b * this->texel(i + 1, j + 1, c));
  }
};

/// The tangent-space normal of the height field scale · h(u, v):
/// normalise(−scale ∂h/∂u, −scale ∂h/∂v, 1), the gradient taken by central
/// differences one texel apart on the bilinear texture (channel 0).
inline glm::dvec3 bumpNormal(const Texture& height, double u, double v, double scale)
{
  const double du = 1.0 / height.width, dv = 1.0 / height.height;
  const double dhdu = (height.sample(u + du, v, 0) - height.sample(u - du, v, 0)) / (2 * du);
  const double dhdv = (height.sample(u, v + dv, 0) - height.sample(u, v - dv, 0)) / (2 * dv);
  return glm::normalize(glm::dvec3(-scale * dhdu, -scale * dhdv, 1.0));
}

} // namespace slnormals

#endif
