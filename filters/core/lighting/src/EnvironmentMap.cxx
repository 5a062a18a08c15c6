#include "shadelab/EnvironmentMap.h"

#include "shadelab/LightingGLSL.h"

#include <algorithm>
#include <cmath>

namespace shadelab
{

namespace
{
constexpr double kPi = 3.14159265358979323846;

/// Index of the interval of cumulative @p cdf (size n + 1, cdf[0] = 0) holding u * cdf[n].
int findInterval(const float* cdf, int n, float u, float& fraction)
{
  const float target = u * cdf[n];
  const int i = std::clamp(static_cast<int>(std::upper_bound(cdf, cdf + n + 1, target) - cdf) - 1, 0, n - 1);
  const float width = cdf[i + 1] - cdf[i];
  fraction = width > 0.0f ? std::clamp((target - cdf[i]) / width, 0.0f, 1.0f) : 0.5f;
  return i;
}
} // namespace

void EnvironmentMap::set(int width, int height, std::vector<float> rgb, const std::string& name)
{
  const std::string prefix = name + ": environment map ";
  if (width < 2 || height < 1 || width != 2 * height)
  {
    throw Error(prefix + "is " + std::to_string(width) + " x " + std::to_string(height) +
      " pixels; an equirectangular environment map must be twice as wide as it is high");
  }
  if (rgb.size() != static_cast<size_t>(3) * width * height)
  {
    throw Error(prefix + "has " + std::to_string(rgb.size()) + " values, not 3 per pixel");
  }
  for (size_t i = 0; i < rgb.size(); ++i)
  {
    if (!std::isfinite(rgb[i]) || rgb[i] < 0.0f)
    {
      throw Error(prefix + "pixel " + std::to_string(i / 3) + " has a negative or non-finite value");
    }
  }
  this->Width = width;
  this->Height = height;
  this->RGB = std::move(rgb);
  // Weights: luminance x sin(theta) of the texel's row (its solid angle), a
  // small floor so that every direction with radiance can be drawn.
  this->Weights.assign(static_cast<size_t>(width) * height, 0.0f);
  this->Columns.assign(static_cast<size_t>(height) * (width + 1), 0.0f);
  this->Rows.assign(static_cast<size_t>(height) + 1, 0.0f);
  double total = 0.0;
  for (int y = 0; y < height; ++y)
  {
    const double theta = kPi * (1.0 - (y + 0.5) / height); // row 0 at the bottom: theta near pi
    const float sinTheta = static_cast<float>(std::sin(theta));
    float* cdf = &this->Columns[static_cast<size_t>(y) * (width + 1)];
    for (int x = 0; x < width; ++x)
    {
      const float* c = &this->RGB[3 * (static_cast<size_t>(y) * width + x)];
      const float luminance = glsl::slLuminance(glm::vec3(c[0], c[1], c[2]));
      const float w = (luminance + 1e-6f) * sinTheta;
      this->Weights[static_cast<size_t>(y) * width + x] = w;
      cdf[x + 1] = cdf[x] + w;
    }
    this->Rows[static_cast<size_t>(y) + 1] = this->Rows[static_cast<size_t>(y)] + cdf[width];
    total += cdf[width];
  }
  this->TotalWeight = total;
}

void EnvironmentMap::setConstant(const glm::vec3& rgb)
{
  std::vector<float> data;
  for (int i = 0; i < 8 * 4; ++i)
  {
    data.insert(data.end(), { rgb.x, rgb.y, rgb.z });
  }
  this->set(8, 4, std::move(data));
}

int EnvironmentMap::texel(const glm::vec3& d) const
{
  const double theta = std::acos(std::clamp(static_cast<double>(d.y), -1.0, 1.0));
  double phi = std::atan2(static_cast<double>(d.x), static_cast<double>(-d.z));
  const double u = (phi + kPi) / (2.0 * kPi);
  const double v = 1.0 - theta / kPi;
  const int x = std::clamp(static_cast<int>(u * this->Width), 0, this->Width - 1);
  const int y = std::clamp(static_cast<int>(v * this->Height), 0, this->Height - 1);
  return y * this->Width + x;
}

glm::vec3 EnvironmentMap::direction(float u, float v) const
{
  const double phi = 2.0 * kPi * u - kPi;
  const double theta = kPi * (1.0 - v);
  const double s = std::sin(theta);
  return glm::vec3(static_cast<float>(s * std::sin(phi)), static_cast<float>(std::cos(theta)),
    static_cast<float>(-s * std::cos(phi)));
}

glm::vec3 EnvironmentMap::radiance(const glm::vec3& d) const
{
  if (this->empty())
  {
    return glm::vec3(0.0f);
  }
  const float* c = &this->RGB[3 * static_cast<size_t>(this->texel(d))];
  return glm::vec3(c[0], c[1], c[2]);
}

glm::vec3 EnvironmentMap::sample(float u1, float u2, float& pdf) const
{
  float fy = 0.0f, fx = 0.0f;
  const int y = findInterval(this->Rows.data(), this->Height, u1, fy);
  const int x = findInterval(&this->Columns[static_cast<size_t>(y) * (this->Width + 1)], this->Width, u2, fx);
  const glm::vec3 d = this->direction((x + fx) / this->Width, (y + fy) / this->Height);
  pdf = this->pdf(d);
  return d;
}

float EnvironmentMap::pdf(const glm::vec3& d) const
{
  if (this->empty() || !(this->TotalWeight > 0.0))
  {
    return 0.0f;
  }
  // Texel probability spread uniformly in (u, v); dω = 2 pi^2 sin(theta) du dv.
  const int t = this->texel(d);
  const double p = this->Weights[static_cast<size_t>(t)] / this->TotalWeight;
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - static_cast<double>(d.y) * d.y));
  if (sinTheta < 1e-8)
  {
    return 0.0f;
  }
  return static_cast<float>(p * this->Width * this->Height / (2.0 * kPi * kPi * sinTheta));
}

} // namespace shadelab
