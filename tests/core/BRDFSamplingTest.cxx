// The BRDF importance samplers (Sampling.h, BRDFSampler.h) and the radiance
// reference built on them: each density is the density of its sampler
// (histograms against the density integrated over bins by quadrature here;
// the density integrates to 1 over the sphere), the mean of f cos / pdf is
// the directional albedo of Albedo.h, and the reference's error falls as
// 1 / sqrt(N) for every model added beyond the lecture ones.
#include "LightingTestUtilities.h"
#include "Quadrature.h"

#include "shadelab/Albedo.h"
#include "shadelab/BRDFSampler.h"
#include "shadelab/RadianceEstimator.h"
#include "shadelab/Sampling.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <functional>

using namespace shadelab;
using namespace shadelab::test;

namespace
{
/// A sampler of facet normals around +z and its claimed density.
struct HalfwaySampler
{
  const char* name;
  double width; ///< the lobe's angular width, for the bins
  std::function<glm::vec3(float, float)> sample;
  std::function<float(const glm::vec3&)> pdf;
};

std::vector<HalfwaySampler> halfwaySamplers()
{
  std::vector<HalfwaySampler> samplers;
  for (float alpha : { 0.05f, 0.3f, 1.0f })
  {
    for (double degrees : { 0.0, 50.0, 85.0 })
    {
      const glm::vec3 V = polar(radians(degrees), 0.7);
      samplers.push_back({ "GGX visible normals", alpha,
        [=](float u1, float u2) { return sampleGGXVisibleNormal(V, alpha, u1, u2); },
        [=](const glm::vec3& H) { return ggxVisibleNormalPdf(V, H, alpha); } });
    }
    samplers.push_back({ "Beckmann", alpha, [=](float u1, float u2) { return sampleBeckmannNormal(alpha, u1, u2); },
      [=](const glm::vec3& H) { return beckmannNormalPdf(H, alpha); } });
  }
  for (glm::vec2 pair : { glm::vec2(0.05f, 0.3f), glm::vec2(0.5f, 0.1f), glm::vec2(1.0f, 0.7f) })
  {
    const float nu = glsl::slAshikhminShirleyExponent(pair.x), nv = glsl::slAshikhminShirleyExponent(pair.y);
    const double width = std::min(pair.x, pair.y);
    samplers.push_back({ "Ward", width, [=](float u1, float u2) { return sampleWardNormal(pair.x, pair.y, u1, u2); },
      [=](const glm::vec3& H) { return wardNormalPdf(H, pair.x, pair.y); } });
    samplers.push_back({ "Ashikhmin-Shirley", width,
      [=](float u1, float u2) { return sampleAshikhminShirleyNormal(nu, nv, u1, u2); },
      [=](const glm::vec3& H) { return ashikhminShirleyNormalPdf(H, nu, nv); } });
  }
  return samplers;
}

/// Polar bin edges from 0 to pi/2 at the lobe's width times 1/4, 1/2, 1, 2, ...
std::vector<double> polarEdges(double width)
{
  std::vector<double> edges{ 0.0 };
  for (double t = 0.25 * width; t < 0.5 * kPi; t *= 2.0)
  {
    edges.push_back(t);
  }
  edges.push_back(0.5 * kPi);
  return edges;
}

/// A material for @p model: k_d, k_s and the lobe's parameters.
slMaterial samplingMaterial(float kd, float ks, float roughness, glm::vec2 pair)
{
  slMaterial m = unitMaterial(30.0f);
  m.diffuse = glm::vec3(kd);
  m.specular = glm::vec3(ks);
  m.roughness = roughness;
  m.roughnessX = pair.x;
  m.roughnessY = pair.y;
  return m;
}

/// The models beyond the lecture ones, and the lecture ones whose sampler
/// the new code also carries (normalised Phong and Blinn-Phong).
const int kSampledModels[] = { glsl::SL_MODEL_PHONG_NORMALIZED, glsl::SL_MODEL_BLINN_PHONG_NORMALIZED,
  glsl::SL_MODEL_COOK_TORRANCE_GGX, glsl::SL_MODEL_COOK_TORRANCE_BECKMANN, glsl::SL_MODEL_OREN_NAYAR,
  glsl::SL_MODEL_WARD, glsl::SL_MODEL_ASHIKHMIN_SHIRLEY };
const int kNewModels[] = { glsl::SL_MODEL_COOK_TORRANCE_GGX, glsl::SL_MODEL_COOK_TORRANCE_BECKMANN,
  glsl::SL_MODEL_OREN_NAYAR, glsl::SL_MODEL_WARD, glsl::SL_MODEL_ASHIKHMIN_SHIRLEY };
} // namespace

TEST(BRDFSampling, FacetNormalHistogramsMatchTheirDensities)
{
  const int samples = 100000;
  for (const HalfwaySampler& s : halfwaySamplers())
  {
    const std::vector<double> edges = polarEdges(s.width);
    const int azimuths = 8;
    std::vector<int> counts((edges.size() - 1) * azimuths, 0);
    Rng rng(5, 1);
    for (int k = 0; k < samples; ++k)
    {
      const float u1 = rng.next(), u2 = rng.next();
      const glm::vec3 H = s.sample(u1, u2);
      ASSERT_NEAR(glm::length(H), 1.0f, 1e-5f) << s.name;
      ASSERT_GE(H.z, 0.0f) << s.name;
      const double theta = std::acos(std::min(1.0f, H.z));
      double phi = std::atan2(H.y, H.x);
      phi = phi < 0.0 ? phi + 2.0 * kPi : phi;
      const size_t i = std::min<size_t>(
        edges.size() - 2, std::upper_bound(edges.begin(), edges.end(), theta) - edges.begin() - 1);
      const int j = std::min(azimuths - 1, static_cast<int>(phi / (2.0 * kPi) * azimuths));
      ++counts[i * azimuths + j];
    }
    double total = 0.0;
    for (size_t i = 0; i + 1 < edges.size(); ++i)
    {
      for (int j = 0; j < azimuths; ++j)
      {
        const double p0 = 2.0 * kPi * j / azimuths, p1 = 2.0 * kPi * (j + 1) / azimuths;
        const double p = composite(
          [&](double t) {
            return composite(
                     [&](double phi) { return double(s.pdf(glm::vec3(polar(t, phi)))); }, graded(p0, p1, {}, 4)) *
              std::sin(t);
          },
          graded(edges[i], edges[i + 1], {}, 4));
        total += p;
        const double observed = double(counts[i * azimuths + j]) / samples;
        EXPECT_NEAR(observed, p, 5.0 * std::sqrt(p * (1.0 - p) / samples) + 2e-5)
          << s.name << " width " << s.width << " bin " << i << ", " << j;
      }
    }
    EXPECT_NEAR(total, 1.0, 1e-4) << s.name << " width " << s.width;
  }
}

TEST(BRDFSampling, DensityIntegratesToOneOverTheSphere)
{
  // The mixture's density of L, integrated in polar coordinates about the
  // mirror direction R, on a grid refined toward R.
  for (int model : kSampledModels)
  {
    for (double degrees : { 10.0, 60.0 })
    {
      const slMaterial m = samplingMaterial(0.4f, 0.6f, 0.2f, glm::vec2(0.1f, 0.3f));
      const glm::vec3 N(0.0f, 0.0f, 1.0f), V = polar(radians(degrees), 0.3);
      const BRDFSampler sampler(model, m, N, glm::vec3(1.0f, 0.0f, 0.0f), V);
      const Frame around(glm::vec3(-V.x, -V.y, V.z));
      const double integral = composite(
        [&](double t) {
          return composite([&](double phi) { return double(sampler.pdf(around.toWorld(polar(t, phi)))); },
                   graded(0.0, 2.0 * kPi, {}, 32)) *
            std::sin(t);
        },
        graded(0.0, kPi, { 0.0 }, 32, 1e-3));
      EXPECT_NEAR(integral, 1.0, 1e-3) << kLightingModels[model].name << " at " << degrees << " degrees";
    }
  }
}

TEST(BRDFSampling, MeanOfWeightsIsTheDirectionalAlbedo)
{
  // By reciprocity the integral of f(L, V) cos(theta_L) over L is the albedo
  // a(theta_V) of Albedo.h (V in the plane of the tangent X and N).
  const int samples = 20000;
  for (int model : kSampledModels)
  {
    for (const glm::vec2& weights : { glm::vec2(0.0f, 1.0f), glm::vec2(0.5f, 0.5f) })
    {
      for (float roughness : { 0.05f, 0.4f })
      {
        for (double degrees : { 0.0, 45.0, 80.0 })
        {
          const bool diffuseOnly = model == glsl::SL_MODEL_OREN_NAYAR;
          const slMaterial m = samplingMaterial(diffuseOnly ? 1.0f : weights.x, weights.y, roughness,
            glm::vec2(roughness, 2.0f * roughness));
          const glm::vec3 N(0.0f, 0.0f, 1.0f), T(1.0f, 0.0f, 0.0f), V = polar(radians(degrees));
          const BRDFSampler sampler(model, m, N, T, V);
          Rng rng(3, 9);
          double sum = 0.0, squares = 0.0;
          for (int k = 0; k < samples; ++k)
          {
            const float c = rng.next(), u1 = rng.next(), u2 = rng.next();
            const glm::vec3 L = sampler.sample(c, u1, u2);
            const float pdf = sampler.pdf(L);
            const glm::vec3 f = glsl::slBRDF(model, m, N, T, L, V);
            const double y = L.z > 0.0f && pdf > 0.0f ? (f.x + f.y + f.z) / 3.0 * L.z / pdf : 0.0;
            sum += y;
            squares += y * y;
          }
          const double mean = sum / samples, sigma = std::sqrt(std::max(0.0, squares / samples - mean * mean) / samples);
          const double albedo = directionalAlbedo(model, m, radians(degrees));
          EXPECT_NEAR(mean, albedo, 5.0 * sigma + 1e-4)
            << kLightingModels[model].name << " roughness " << roughness << " k_d " << weights.x << " at "
            << degrees << " degrees";
        }
      }
    }
  }
}

TEST(BRDFSampling, ReferenceErrorFollowsOneOverSqrtNForEveryNewModel)
{
  // MIS under a smooth sky with a bright patch and a small distant light:
  // RMSE over points and seeds against a 16384-sample estimate falls by ~2
  // per 4x samples.
  EnvironmentMap sky;
  const int width = 32, height = 16;
  std::vector<float> rgb;
  for (int row = 0; row < height; ++row)
  {
    for (int column = 0; column < width; ++column)
    {
      const float v = (row + 0.5f) / height, u = (column + 0.5f) / width;
      const float patch = std::abs(u - 0.3f) < 0.08f && std::abs(v - 0.7f) < 0.1f ? 20.0f : 0.0f;
      rgb.insert(rgb.end(), { 0.2f + v + patch, 0.3f + 0.5f * u + patch, 0.5f + patch });
    }
  }
  sky.set(width, height, rgb);
  for (int model : kNewModels)
  {
    ReferenceSetup setup;
    setup.lights = { directionalFrom(glm::normalize(glm::vec3(0.3f, 0.5f, 0.8f))) };
    setup.directionalAngularRadius = 0.05f;
    setup.environment = &sky;
    setup.material = samplingMaterial(0.3f, 0.7f, 0.25f, glm::vec2(0.15f, 0.4f));
    setup.model = model;
    setup.strategy = SamplingStrategy::MIS;
    auto estimate = [&](int point, int samples, int seed) {
      setup.samples = samples;
      setup.seed = static_cast<std::uint64_t>(seed);
      const glm::vec3 N = glm::normalize(glm::vec3(std::sin(point * 1.3f), std::cos(point * 0.7f), 1.5f));
      const glm::vec3 T(std::cos(point * 0.4f), std::sin(point * 0.4f), 0.0f);
      const glm::vec3 eye = 3.0f * glm::normalize(glm::vec3(std::cos(point * 2.1f), 0.4f, 1.0f));
      return estimateRadiance(setup, glm::vec3(0.0f), N, T, eye, static_cast<std::uint64_t>(point)).mean.y;
    };
    const int points = 12;
    std::vector<double> truth;
    for (int p = 0; p < points; ++p)
    {
      truth.push_back(estimate(p, 16384, 99));
    }
    std::vector<double> rmse;
    for (int samples : { 16, 64, 256 })
    {
      double sum = 0.0;
      for (int seed = 1; seed <= 8; ++seed)
      {
        for (int p = 0; p < points; ++p)
        {
          const double d = estimate(p, samples, seed) - truth[p];
          sum += d * d;
        }
      }
      rmse.push_back(std::sqrt(sum / (8 * points)));
    }
    EXPECT_NEAR(rmse[0] / rmse[1], 2.0, 0.5) << kLightingModels[model].name;
    EXPECT_NEAR(rmse[1] / rmse[2], 2.0, 0.5) << kLightingModels[model].name;
    std::printf("%s: RMSE at 16, 64, 256 samples %.4g %.4g %.4g\n", kLightingModels[model].name, rmse[0], rmse[1],
      rmse[2]);
  }
}
