#ifndef shadelab_EnvironmentMap_h
#define shadelab_EnvironmentMap_h
/**
 * @file EnvironmentMap.h
 * @brief An equirectangular (latitude-longitude) HDR environment map as a
 * light source: radiance by direction and importance sampling of directions
 * in proportion to luminance x sin(theta), with its density per unit solid
 * angle.
 *
 * Layout: width = 2 x height, linear RGB, row 0 at the bottom (as
 * slImageReader delivers images). Directions are y-up: the top row is +y,
 * the centre column looks along -z, u grows toward +x (phi = atan2(x, -z)).
 * Lookups are nearest-texel, so the map is a piecewise-constant function
 * whose integral the sampler reproduces exactly.
 */

#include "shadelab/Error.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace shadelab
{

class EnvironmentMap
{
public:
  /// Checks and stores @p rgb (3 floats per texel, row 0 at the bottom).
  /// Throws shadelab::Error "NAME: environment map REASON" (wrong layout,
  /// negative or non-finite values), @p name standing for the image.
  void set(int width, int height, std::vector<float> rgb, const std::string& name = "environment");

  /// A constant map of radiance @p rgb (a small 2:1 map).
  void setConstant(const glm::vec3& rgb);

  bool empty() const { return this->Width == 0; }
  int width() const { return this->Width; }
  int height() const { return this->Height; }

  /// Radiance arriving from unit direction @p direction (toward the sky).
  glm::vec3 radiance(const glm::vec3& direction) const;

  /// A direction drawn in proportion to luminance x sin(theta); @p pdf gets
  /// its density per unit solid angle.
  glm::vec3 sample(float u1, float u2, float& pdf) const;

  /// The density of sample() at @p direction.
  float pdf(const glm::vec3& direction) const;

private:
  int texel(const glm::vec3& direction) const;
  glm::vec3 direction(float u, float v) const;

  int Width = 0;
  int Height = 0;
  std::vector<float> RGB;
  std::vector<float> Rows;     ///< marginal CDF over rows, Height + 1 entries
  std::vector<float> Columns;  ///< conditional CDF per row, Height x (Width + 1)
  std::vector<float> Weights;  ///< sampling weight per texel
  double TotalWeight = 0.0;
};

} // namespace shadelab

#endif
