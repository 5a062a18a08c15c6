// Degenerate geometry must shade to finite numbers, never NaN or infinity.
#include "LightingTestUtilities.h"
#include "TableExpectations.h"

#include "shadelab/LightingTables.h"
#include "shadelab/ShadePoint.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>
#include <limits>

using namespace shadelab;
using namespace shadelab::test;

namespace
{
std::vector<glsl::slLight> everyLightType()
{
  glsl::slLight point = whiteLight(glsl::SL_LIGHT_POINT);
  point.position = glm::vec3(0.0f, 0.0f, 1.0f);
  point.attenuation = glm::vec3(0.0f, 0.0f, 1.0f);
  glsl::slLight spot = whiteLight(glsl::SL_LIGHT_SPOT);
  spot.position = glm::vec3(0.0f, 0.0f, 1.0f);
  spot.cosCutoff = 0.5f;
  spot.cosInner = 0.7f;
  spot.exponent = 3.0f;
  glsl::slLight ambient = whiteLight(glsl::SL_LIGHT_AMBIENT);
  ambient.ambient = glm::vec3(0.1f);
  return { directionalFrom(glm::vec3(0.0f, 0.0f, 1.0f)), point, spot, ambient };
}

void expectFinite(const glsl::slTerms& t, const std::string& what)
{
  const glm::vec3 parts[] = { t.ambient, t.diffuse, t.specular, t.emission };
  for (const glm::vec3& p : parts)
  {
    for (int i = 0; i < 3; ++i)
    {
      EXPECT_TRUE(std::isfinite(p[i])) << what;
    }
  }
}

const std::vector<int> kAllModels = allModels();
} // namespace

TEST(Degenerate, ZeroNormalGivesOnlyAmbientAndEmission)
{
  glsl::slMaterial m = unitMaterial(32);
  m.ambient = glm::vec3(1.0f);
  for (int model : kAllModels)
  {
    const auto t = shadePoint(everyLightType(), m, model, glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0, 0, 5));
    expectFinite(t, "zero normal");
    EXPECT_EQ(t.diffuse, glm::vec3(0.0f));
    EXPECT_EQ(t.specular, glm::vec3(0.0f));
    EXPECT_GT(t.ambient.x, 0.0f);
  }
}

/// Diffuse of a white unit light at N.L = 1 on k_d = 1: rho, or rho/pi for
/// the energy-normalised models (docs/lighting-core.md).
/// The reflection factors TableExpectations.h expects of @p model for unit
/// N, L, V (V may be zero: no view direction) and unitMaterial(8)'s
/// parameters, with the tangent along +x.
test::ReflectionFactors expectedFactors(int model, const glm::vec3& N, const glm::vec3& L, const glm::vec3& V)
{
  const SceneMaterial d;
  return test::modelExpectations().at(modelInfo(static_cast<ShadingModel>(model)).name)(test::ReflectionGeometry{
    glm::dvec3(N), glm::dvec3(L), glm::dvec3(V), 8.0, glm::dvec3(1.0, 0.0, 0.0), d.roughness, d.roughnessX,
    d.roughnessY, d.ior });
}

TEST(Degenerate, LightAtTheShadedPoint)
{
  // A positional light exactly at the shaded point has no direction: it adds
  // its ambient term (reach 1: d = 0 gives f_att = min(1, 1/(c3 d^2)) = 1)
  // and nothing else. Beside it, a directional light from +z shades as usual.
  const glm::vec3 p(0, 0, 1), n(0, 0, 1), eye(0, 0, 5);
  glsl::slMaterial m = unitMaterial(8);
  m.ambient = glm::vec3(1.0f);
  m.emission = glm::vec3(0.5f);
  glsl::slLight atPoint = everyLightType()[1];
  ASSERT_EQ(atPoint.position, p);
  atPoint.ambient = glm::vec3(0.25f);
  for (int model : kAllModels)
  {
    const auto alone = shadePoint({ atPoint }, m, model, p, n, eye);
    expectFinite(alone, "light at point");
    EXPECT_EQ(alone.diffuse, glm::vec3(0.0f)) << model;
    EXPECT_EQ(alone.specular, glm::vec3(0.0f)) << model;
    EXPECT_EQ(alone.ambient, glm::vec3(0.25f)) << model;
    EXPECT_EQ(alone.emission, glm::vec3(0.5f)) << model;

    const auto both = shadePoint({ atPoint, directionalFrom(n) }, m, model, p, n, eye);
    EXPECT_NEAR(both.diffuse.x, expectedFactors(model, n, n, glm::normalize(eye - p)).diffuse, 1e-6f) << model;
    EXPECT_EQ(both.ambient, glm::vec3(0.25f)) << model;
  }
}

TEST(Degenerate, EyeAtTheShadedPoint)
{
  // The eye at the point leaves no view direction: the view-independent
  // terms are exact, and specular stays finite and within its peak value.
  const glm::vec3 p(0.0f), n(0, 0, 1);
  for (int model : kAllModels)
  {
    const auto t = shadePoint({ directionalFrom(n) }, unitMaterial(8), model, p, n, p);
    expectFinite(t, "eye at point");
    EXPECT_NEAR(t.diffuse.x, expectedFactors(model, n, n, glm::vec3(0.0f)).diffuse, 1e-6f) << model;
    EXPECT_EQ(t.ambient, glm::vec3(0.0f)) << model;
    // At most the model's peak: its expected specular factor with the eye
    // on the mirror direction (here the normal, as the light is).
    const double peak = expectedFactors(model, n, n, n).specular;
    EXPECT_GE(t.specular.x, 0.0f) << model;
    EXPECT_LE(t.specular.x, static_cast<float>(peak) + 1e-6f) << model;
  }
  // Every light type at once stays finite too.
  for (int model : kAllModels)
  {
    expectFinite(shadePoint(everyLightType(), unitMaterial(8), model, p, n, p), "eye at point, every light");
  }
}

TEST(Degenerate, GrazingLightNDotLExactlyZero)
{
  const glsl::slLight light = directionalFrom(glm::vec3(1.0f, 0.0f, 0.0f));
  for (int model : kAllModels)
  {
    const auto t = shadePoint({ light }, unitMaterial(0), model, glm::vec3(0.0f), glm::vec3(0, 0, 1),
      glm::vec3(-1.0f, 0.0f, 0.0f));
    expectFinite(t, "N.L = 0");
    EXPECT_EQ(t.diffuse.x, 0.0f);
    EXPECT_EQ(t.specular.x, 0.0f);
  }
}

TEST(Degenerate, ExtremeShininess)
{
  for (float n : { 0.0f, 1e-6f, 1e4f })
  {
    for (int model : kAllModels)
    {
      for (double eyeDegrees : { -60.0, -30.0, 0.0, 45.0 })
      {
        const auto t = shadePoint(everyLightType(), unitMaterial(n), model, glm::vec3(0.3f, 0.0f, 0.0f),
          glm::vec3(0, 0, 1), 5.0f * polar(radians(eyeDegrees)));
        expectFinite(t, "shininess " + std::to_string(n));
      }
    }
  }
  // Shininess 0: the lobe is flat, 1 wherever the light is in front.
  const auto flat = shadePoint({ directionalFrom(polar(radians(30))) }, unitMaterial(0), glsl::SL_MODEL_PHONG,
    glm::vec3(0.0f), glm::vec3(0, 0, 1), 5.0f * polar(radians(10)));
  EXPECT_NEAR(flat.specular.x, 1.0, 1e-6);
}

TEST(Degenerate, NonFiniteNormalIsTreatedAsNoNormal)
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (const glm::vec3& n : { glm::vec3(nan, 0, 1), glm::vec3(inf, 0, 0) })
  {
    const auto t = shadePoint(everyLightType(), unitMaterial(8), glsl::SL_MODEL_BLINN_PHONG, glm::vec3(0.0f), n,
      glm::vec3(0, 0, 5));
    expectFinite(t, "non-finite normal");
  }
}
