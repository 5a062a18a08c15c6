#include "shadelab/Sampling.h"

#include <algorithm>
#include <cmath>

namespace shadelab
{

namespace
{
constexpr float kPi = 3.14159265358979f;
}

Rng::Rng(std::uint64_t seed, std::uint64_t stream)
  : Increment((stream << 1u) | 1u)
{
  this->nextUInt();
  this->State += seed;
  this->nextUInt();
}

std::uint32_t Rng::nextUInt()
{
  const std::uint64_t old = this->State;
  this->State = old * 6364136223846793005ULL + this->Increment;
  const std::uint32_t shifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
  const std::uint32_t rotation = static_cast<std::uint32_t>(old >> 59u);
  return (shifted >> rotation) | (shifted << ((~rotation + 1u) & 31u));
}

float Rng::next()
{
  // 24 random bits: exactly representable, strictly below 1.
  return static_cast<float>(this->nextUInt() >> 8) * (1.0f / 16777216.0f);
}

Frame::Frame(const glm::vec3& normal)
  : N(normal)
{
  const float sign = std::copysign(1.0f, normal.z);
  const float a = -1.0f / (sign + normal.z);
  const float b = normal.x * normal.y * a;
  this->T = glm::vec3(1.0f + sign * normal.x * normal.x * a, sign * b, -sign * normal.x);
  this->B = glm::vec3(b, sign + normal.y * normal.y * a, -normal.y);
}

glm::vec3 sampleUniformHemisphere(float u1, float u2)
{
  const float z = u1;
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * u2;
  return glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
}

float uniformHemispherePdf()
{
  return 1.0f / (2.0f * kPi);
}

glm::vec3 sampleCosineHemisphere(float u1, float u2)
{
  const float r = std::sqrt(u1);
  const float phi = 2.0f * kPi * u2;
  return glm::vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u1)));
}

float cosineHemispherePdf(float cosTheta)
{
  return std::max(cosTheta, 0.0f) / kPi;
}

glm::vec3 sampleUniformCone(float u1, float u2, float cosMax)
{
  const float z = 1.0f - u1 * (1.0f - cosMax);
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * u2;
  return glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
}

float uniformConePdf(float cosMax)
{
  return 1.0f / (2.0f * kPi * (1.0f - cosMax));
}

glm::vec3 samplePhongLobe(float u1, float u2, float n)
{
  const float z = std::pow(u1, 1.0f / (n + 1.0f));
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * u2;
  return glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
}

float phongLobePdf(float cosAlpha, float n)
{
  return cosAlpha > 0.0f ? (n + 1.0f) / (2.0f * kPi) * std::pow(cosAlpha, n) : 0.0f;
}

float powerHeuristic(float a, float b)
{
  const float a2 = a * a, b2 = b * b;
  return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

} // namespace shadelab
