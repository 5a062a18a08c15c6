#include "shadelab/Sampling.h"

#include "shadelab/LightingGLSL.h"

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

Frame::Frame(const glm::vec3& normal, const glm::vec3& tangent)
  : T(tangent)
  , B(glm::cross(normal, tangent))
  , N(normal)
{
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

namespace
{
/// The unit vector at cosine @p cosTheta from +z and azimuth @p phi.
glm::vec3 fromAngles(float cosTheta, float phi)
{
  const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  return glm::vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
}

/// The azimuth phi with tan(phi) = ratio tan(2 pi u) in the quadrant of 2 pi u:
/// density ratio / (2 pi (ratio^2 cos^2 phi + sin^2 phi)).
float stretchedAzimuth(float u, float ratio)
{
  const float psi = 2.0f * kPi * u;
  return std::atan2(ratio * std::sin(psi), std::cos(psi));
}

/// cos^2 and sin^2 of the azimuth of @p H (1 and 0 at the pole, where the
/// densities below do not depend on them).
glm::vec2 azimuthSquares(const glm::vec3& H)
{
  const float across = H.x * H.x + H.y * H.y;
  return across > 0.0f ? glm::vec2(H.x * H.x, H.y * H.y) / across : glm::vec2(1.0f, 0.0f);
}
} // namespace

glm::vec3 sampleGGXVisibleNormal(const glm::vec3& V, float alpha, float u1, float u2)
{
  // Heitz 2018, listing 1, isotropic: stretch V to the hemisphere
  // configuration, sample the projected half disk, unstretch.
  const glm::vec3 Vh = glm::normalize(glm::vec3(alpha * V.x, alpha * V.y, V.z));
  const float lengthSquared = Vh.x * Vh.x + Vh.y * Vh.y;
  const glm::vec3 T1 =
    lengthSquared > 0.0f ? glm::vec3(-Vh.y, Vh.x, 0.0f) / std::sqrt(lengthSquared) : glm::vec3(1.0f, 0.0f, 0.0f);
  const glm::vec3 T2 = glm::cross(Vh, T1);
  const float r = std::sqrt(u1), phi = 2.0f * kPi * u2;
  const float t1 = r * std::cos(phi);
  const float s = 0.5f * (1.0f + Vh.z);
  const float t2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - t1 * t1)) + s * r * std::sin(phi);
  const glm::vec3 Nh = t1 * T1 + t2 * T2 + std::sqrt(std::max(0.0f, 1.0f - t1 * t1 - t2 * t2)) * Vh;
  return glm::normalize(glm::vec3(alpha * Nh.x, alpha * Nh.y, std::max(0.0f, Nh.z)));
}

float ggxVisibleNormalPdf(const glm::vec3& V, const glm::vec3& H, float alpha)
{
  if (!(V.z > 0.0f))
  {
    return 0.0f;
  }
  const float a2 = alpha * alpha;
  const float g1 = 2.0f * V.z / (V.z + std::sqrt(a2 * (1.0f - V.z * V.z) + V.z * V.z));
  return g1 * std::max(0.0f, glm::dot(V, H)) * glsl::slGGXDistribution(H.z, alpha) / V.z;
}

glm::vec3 sampleBeckmannNormal(float alpha, float u1, float u2)
{
  const float tan2 = -alpha * alpha * std::log1p(-u1);
  return fromAngles(1.0f / std::sqrt(1.0f + tan2), 2.0f * kPi * u2);
}

float beckmannNormalPdf(const glm::vec3& H, float alpha)
{
  return glsl::slBeckmannDistribution(H.z, alpha) * std::max(H.z, 0.0f);
}

glm::vec3 sampleWardNormal(float ax, float ay, float u1, float u2)
{
  const float phi = stretchedAzimuth(u2, ay / ax);
  const float c = std::cos(phi), s = std::sin(phi);
  const float tan2 = -std::log1p(-u1) / (c * c / (ax * ax) + s * s / (ay * ay));
  return fromAngles(1.0f / std::sqrt(1.0f + tan2), phi);
}

float wardNormalPdf(const glm::vec3& H, float ax, float ay)
{
  if (!(H.z > 0.0f))
  {
    return 0.0f;
  }
  const float e = (H.x * H.x / (ax * ax) + H.y * H.y / (ay * ay)) / (H.z * H.z);
  return std::exp(-e) / (kPi * ax * ay * H.z * H.z * H.z);
}

glm::vec3 sampleAshikhminShirleyNormal(float nu, float nv, float u1, float u2)
{
  const float phi = stretchedAzimuth(u2, std::sqrt((nu + 1.0f) / (nv + 1.0f)));
  const float c = std::cos(phi), s = std::sin(phi);
  const float e = nu * c * c + nv * s * s;
  return fromAngles(std::pow(1.0f - u1, 1.0f / (e + 1.0f)), phi);
}

float ashikhminShirleyNormalPdf(const glm::vec3& H, float nu, float nv)
{
  if (!(H.z > 0.0f))
  {
    return 0.0f;
  }
  const glm::vec2 cs = azimuthSquares(H);
  return std::sqrt((nu + 1.0f) * (nv + 1.0f)) / (2.0f * kPi) * std::pow(H.z, nu * cs.x + nv * cs.y);
}

glm::vec3 reflectAbout(const glm::vec3& V, const glm::vec3& H)
{
  return 2.0f * glm::dot(V, H) * H - V;
}

float reflectedPdf(float pdfH, const glm::vec3& V, const glm::vec3& H)
{
  const float vh = std::abs(glm::dot(V, H));
  return vh > 0.0f ? pdfH / (4.0f * vh) : 0.0f;
}

float powerHeuristic(float a, float b)
{
  const float a2 = a * a, b2 = b * b;
  return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

} // namespace shadelab
