#include "shadelab/RadianceEstimator.h"

#include "shadelab/BRDFSampler.h"
#include "shadelab/LightingTables.h"
#include "shadelab/Sampling.h"

#include <algorithm>
#include <cmath>

namespace shadelab
{

namespace
{
/// A light seen from the shaded point: a cone of uniform radiance.
struct Cone
{
  glm::vec3 axis;
  float cosMax;
  glm::vec3 radiance;
};

/// The scene's lights as cones seen from P.
std::vector<Cone> conesAt(const ReferenceSetup& s, const glm::vec3& P)
{
  std::vector<Cone> cones;
  if (!s.useLights)
  {
    return cones;
  }
  for (const glsl::slLight& light : s.lights)
  {
    if (!lightHasDirection(light.type))
    {
      continue;
    }
    const glm::vec3 axis = glsl::slDirectionToLight(light, P);
    float sinAlpha = std::sin(s.directionalAngularRadius);
    if (lightTakes(static_cast<LightType>(light.type), kLightPosition))
    {
      const float d = glm::length(light.position - P);
      if (!(d > s.lightRadius))
      {
        continue; // inside the light: no direction
      }
      sinAlpha = s.lightRadius / d;
    }
    const float reach = light.intensity * glsl::slLightReach(light, P, axis);
    if (glm::length(axis) == 0.0f || !(sinAlpha > 0.0f) || !(reach > 0.0f))
    {
      continue;
    }
    Cone c;
    c.axis = axis;
    c.cosMax = std::sqrt(std::max(0.0f, 1.0f - sinAlpha * sinAlpha));
    c.radiance = reach * light.diffuse / (glsl::SL_PI * sinAlpha * sinAlpha);
    cones.push_back(c);
  }
  return cones;
}

/// Everything fixed at one point.
struct PointContext
{
  const ReferenceSetup& s;
  glm::vec3 N, T, V;
  Frame frame;
  std::vector<Cone> cones;
  BRDFSampler brdf;
  float environmentChoice; ///< light sampling: probability of the environment
};

glm::vec3 incident(const PointContext& c, const glm::vec3& w)
{
  glm::vec3 L(0.0f);
  if (c.s.environment && !c.s.environment->empty())
  {
    L += c.s.environmentScale * c.s.environment->radiance(w);
  }
  for (const Cone& cone : c.cones)
  {
    if (glm::dot(w, cone.axis) >= cone.cosMax)
    {
      L += cone.radiance;
    }
  }
  return L;
}

/// f_r L_i cos(theta) for incident direction w.
glm::vec3 integrand(const PointContext& c, const glm::vec3& w)
{
  const float cosTheta = glm::dot(c.N, w);
  if (cosTheta <= 0.0f)
  {
    return glm::vec3(0.0f);
  }
  return glsl::slBRDF(c.s.model, c.s.material, c.N, c.T, w, c.V) * incident(c, w) * cosTheta;
}

glm::vec3 sampleBRDF(const PointContext& c, Rng& rng)
{
  const float choice = rng.next(), u1 = rng.next(), u2 = rng.next();
  return c.brdf.sample(choice, u1, u2);
}

float lightPdf(const PointContext& c, const glm::vec3& w)
{
  float pdf = 0.0f;
  if (c.environmentChoice > 0.0f)
  {
    pdf += c.environmentChoice * c.s.environment->pdf(w);
  }
  const float perCone = c.cones.empty() ? 0.0f : (1.0f - c.environmentChoice) / c.cones.size();
  for (const Cone& cone : c.cones)
  {
    if (glm::dot(w, cone.axis) >= cone.cosMax)
    {
      pdf += perCone * uniformConePdf(cone.cosMax);
    }
  }
  return pdf;
}

glm::vec3 sampleLight(const PointContext& c, Rng& rng)
{
  const float choice = rng.next(), u1 = rng.next(), u2 = rng.next();
  if (choice < c.environmentChoice)
  {
    float pdf = 0.0f;
    return c.s.environment->sample(u1, u2, pdf);
  }
  const size_t k = std::min(c.cones.size() - 1,
    static_cast<size_t>((choice - c.environmentChoice) / (1.0f - c.environmentChoice) * c.cones.size()));
  return Frame(c.cones[k].axis).toWorld(sampleUniformCone(u1, u2, c.cones[k].cosMax));
}

/// f / p, or 0 where the density vanishes.
glm::vec3 weighted(const glm::vec3& f, float pdf)
{
  return pdf > 0.0f ? f / pdf : glm::vec3(0.0f);
}

/// One iteration's estimate of the integral.
glm::vec3 oneEstimate(const PointContext& c, SamplingStrategy strategy, bool haveLights, Rng& rng)
{
  switch (strategy)
  {
    case SamplingStrategy::Uniform:
    {
      const glm::vec3 w = c.frame.toWorld(sampleUniformHemisphere(rng.next(), rng.next()));
      return weighted(integrand(c, w), uniformHemispherePdf());
    }
    case SamplingStrategy::Cosine:
    {
      const glm::vec3 w = c.frame.toWorld(sampleCosineHemisphere(rng.next(), rng.next()));
      return weighted(integrand(c, w), cosineHemispherePdf(glm::dot(c.N, w)));
    }
    case SamplingStrategy::BRDF:
    {
      const glm::vec3 w = sampleBRDF(c, rng);
      return weighted(integrand(c, w), c.brdf.pdf(w));
    }
    case SamplingStrategy::Light:
    {
      if (!haveLights)
      {
        return glm::vec3(0.0f);
      }
      const glm::vec3 w = sampleLight(c, rng);
      return weighted(integrand(c, w), lightPdf(c, w));
    }
    case SamplingStrategy::MIS:
    default:
    {
      const glm::vec3 wb = sampleBRDF(c, rng);
      const float pbb = c.brdf.pdf(wb);
      if (!haveLights)
      {
        return weighted(integrand(c, wb), pbb);
      }
      const float plb = lightPdf(c, wb);
      glm::vec3 sum = powerHeuristic(pbb, plb) * weighted(integrand(c, wb), pbb);
      const glm::vec3 wl = sampleLight(c, rng);
      const float pll = lightPdf(c, wl), pbl = c.brdf.pdf(wl);
      sum += powerHeuristic(pll, pbl) * weighted(integrand(c, wl), pll);
      return sum;
    }
  }
}

} // namespace

RadianceEstimate estimateRadiance(
  const ReferenceSetup& s, const glm::vec3& P, const glm::vec3& normal, const glm::vec3& tangent, const glm::vec3& eye,
  std::uint64_t stream)
{
  RadianceEstimate result;
  result.mean = s.material.emission;
  const glm::vec3 N = glsl::slSafeNormalize(normal);
  if (glm::length(N) == 0.0f || s.samples < 1)
  {
    return result;
  }
  const glm::vec3 V = glsl::slSafeNormalize(eye - P);
  PointContext c{ s, N, tangent, V, Frame(N), conesAt(s, P), BRDFSampler(s.model, s.material, N, tangent, V), 0.0f };
  const bool haveEnvironment = s.environment && !s.environment->empty() && s.environmentScale > 0.0f;
  c.environmentChoice = haveEnvironment ? (c.cones.empty() ? 1.0f : 0.5f) : 0.0f;
  const bool haveLights = haveEnvironment || !c.cones.empty();

  Rng rng(s.seed, stream);
  glm::dvec3 sum(0.0), sumSquares(0.0);
  for (int k = 0; k < s.samples; ++k)
  {
    glm::dvec3 y(oneEstimate(c, s.strategy, haveLights, rng));
    if (!std::isfinite(y.x) || !std::isfinite(y.y) || !std::isfinite(y.z))
    {
      y = glm::dvec3(0.0);
    }
    sum += y;
    sumSquares += y * y;
  }
  const double n = s.samples;
  const glm::dvec3 mean = sum / n;
  glm::dvec3 variance(0.0);
  if (s.samples > 1)
  {
    variance = glm::max((sumSquares - n * mean * mean) / (n - 1.0), glm::dvec3(0.0));
  }
  result.mean += glm::vec3(mean);
  result.stdError = glm::vec3(glm::sqrt(variance / n));
  return result;
}

} // namespace shadelab
