// The lecture formulas, checked against values computed here from <cmath>.
#include "LightingTestUtilities.h"

#include "shadelab/LightingTables.h"
#include "shadelab/ShadePoint.h"

#include <gtest/gtest.h>

#include <vector>

using namespace shadelab;
using namespace shadelab::test;

namespace
{
const glm::vec3 kOrigin(0.0f);
const glm::vec3 kUp(0.0f, 0.0f, 1.0f);

glsl::slTerms shadeOne(const glsl::slLight& light, const glsl::slMaterial& m, int model, const glm::vec3& eye,
  const glm::vec3& point = kOrigin, const glm::vec3& normal = kUp)
{
  return shadePoint(std::vector<glsl::slLight>{ light }, m, model, point, normal, eye);
}
} // namespace

TEST(CosineLaw, DiffuseFollowsClampedCosine)
{
  const double angles[] = { 0.0, 60.0, 90.0, 120.0, 180.0 };
  for (double degrees : angles)
  {
    const glsl::slLight light = directionalFrom(polar(radians(degrees)));
    const auto t = shadeOne(light, unitMaterial(1.0f), glsl::SL_MODEL_LAMBERT, glm::vec3(0, 0, 5));
    const double expected = std::max(0.0, std::cos(radians(degrees)));
    EXPECT_NEAR(t.diffuse.x, expected, 1e-6) << degrees << " degrees";
    EXPECT_GE(t.diffuse.x, 0.0f) << "light from behind must give 0, never negative";
  }
  // The exact values the lecture quotes: 1 at 0 degrees, 1/2 at 60 degrees.
  EXPECT_NEAR(shadeOne(directionalFrom(polar(0)), unitMaterial(1), 0, glm::vec3(0, 0, 5)).diffuse.x, 1.0, 1e-6);
  EXPECT_NEAR(
    shadeOne(directionalFrom(polar(radians(60))), unitMaterial(1), 0, glm::vec3(0, 0, 5)).diffuse.x, 0.5, 1e-6);
}

TEST(CosineLaw, ColoursMultiplyComponentwise)
{
  glsl::slLight light = directionalFrom(polar(radians(60.0)));
  light.diffuse = glm::vec3(1.0f, 0.5f, 0.25f);
  light.intensity = 2.0f;
  glsl::slMaterial m = unitMaterial(1.0f);
  m.diffuse = glm::vec3(0.2f, 0.4f, 0.8f);
  const auto t = shadeOne(light, m, glsl::SL_MODEL_LAMBERT, glm::vec3(0, 0, 5));
  EXPECT_NEAR(t.diffuse.x, 2.0 * 1.0 * 0.2 * 0.5, 1e-6);
  EXPECT_NEAR(t.diffuse.y, 2.0 * 0.5 * 0.4 * 0.5, 1e-6);
  EXPECT_NEAR(t.diffuse.z, 2.0 * 0.25 * 0.8 * 0.5, 1e-6);
}

// Sweep the eye around the plane of incidence and return the angle (from +z,
// negative toward -x) where the specular term peaks, and that peak value.
static std::pair<double, double> specularPeak(int model, double lightDegrees, float shininess)
{
  const glsl::slLight light = directionalFrom(polar(radians(lightDegrees)));
  double bestAngle = 0.0, best = -1.0;
  for (double eye = -89.9; eye <= 89.9; eye += 0.1)
  {
    const glm::vec3 eyePosition = 10.0f * polar(radians(eye));
    const double s = shadeOne(light, unitMaterial(shininess), model, eyePosition).specular.x;
    if (s > best)
    {
      best = s;
      bestAngle = eye;
    }
  }
  return { bestAngle, best };
}

TEST(Specular, PhongPeaksAtTheMirrorDirection)
{
  const auto peak = specularPeak(glsl::SL_MODEL_PHONG, 30.0, 20.0f);
  EXPECT_NEAR(peak.first, -30.0, 0.11);
  EXPECT_NEAR(peak.second, 1.0, 1e-4);
}

TEST(Specular, BlinnPhongPeaksAtTheMirrorDirection)
{
  const auto peak = specularPeak(glsl::SL_MODEL_BLINN_PHONG, 45.0, 20.0f);
  EXPECT_NEAR(peak.first, -45.0, 0.11);
  EXPECT_NEAR(peak.second, 1.0, 1e-4);
}

TEST(Specular, LobeShapesAwayFromThePeak)
{
  // Eye 20 degrees off the mirror direction, in the plane of incidence:
  // Phong's R.V = cos 20; Blinn-Phong's N.H = cos 10 (H bisects L and V).
  const double n = 16.0;
  const glsl::slLight light = directionalFrom(polar(radians(40.0)));
  const glm::vec3 eye = 10.0f * polar(radians(-20.0));
  const double phong = shadeOne(light, unitMaterial(16), glsl::SL_MODEL_PHONG, eye).specular.x;
  const double blinn = shadeOne(light, unitMaterial(16), glsl::SL_MODEL_BLINN_PHONG, eye).specular.x;
  EXPECT_NEAR(phong, std::pow(std::cos(radians(20.0)), n), 1e-5);
  EXPECT_NEAR(blinn, std::pow(std::cos(radians(10.0)), n), 1e-5);
}

TEST(Specular, NoHighlightWhenTheLightIsBehind)
{
  for (int model : { glsl::SL_MODEL_PHONG, glsl::SL_MODEL_BLINN_PHONG, glsl::SL_MODEL_PHONG_NORMALIZED,
         glsl::SL_MODEL_BLINN_PHONG_NORMALIZED })
  {
    for (double lightDegrees : { 90.5, 100.0, 150.0 }) // exactly 90: Degenerate.GrazingLight...
    {
      const glsl::slLight light = directionalFrom(polar(radians(lightDegrees)));
      // An eye placed where a mirror about the surface would see the light.
      const glm::vec3 eye = 10.0f * polar(radians(lightDegrees - 180.0));
      const auto t = shadeOne(light, unitMaterial(1.0f), model, eye);
      EXPECT_EQ(t.specular.x, 0.0f) << "model " << model << ", light at " << lightDegrees;
      EXPECT_EQ(t.diffuse.x, 0.0f);
    }
  }
}

TEST(Specular, LambertModelsHaveNoSpecular)
{
  const glsl::slLight light = directionalFrom(polar(radians(30.0)));
  for (int model : { glsl::SL_MODEL_LAMBERT, glsl::SL_MODEL_LAMBERT_NORMALIZED })
  {
    EXPECT_EQ(shadeOne(light, unitMaterial(8), model, 10.0f * polar(radians(-30.0))).specular.x, 0.0f);
  }
}

TEST(Attenuation, ClampedAtOne)
{
  glsl::slLight light = whiteLight(glsl::SL_LIGHT_POINT);
  light.position = glm::vec3(0.0f, 0.0f, 2.0f); // straight above, d = 2
  const glm::vec3 eye(0, 0, 10);
  struct Case
  {
    glm::vec3 c;
    double expected;
  };
  const Case cases[] = {
    { { 1.0f, 0.0f, 0.0f }, 1.0 },                          // no attenuation
    { { 0.5f, 0.0f, 0.0f }, 1.0 },                          // 1/0.5 = 2, clamped
    { { 0.0f, 0.0f, 0.1f }, 1.0 },                          // 1/0.4 = 2.5, clamped
    { { 1.0f, 0.5f, 0.25f }, 1.0 / (1.0 + 1.0 + 1.0) },     // 1/3
    { { 0.0f, 0.0f, 1.0f }, 1.0 / 4.0 },                    // physics: 1/d^2
    { { 0.0f, 0.0f, 0.0f }, 1.0 },                          // all zero: none
  };
  for (const Case& c : cases)
  {
    light.attenuation = c.c;
    EXPECT_NEAR(shadeOne(light, unitMaterial(1), glsl::SL_MODEL_LAMBERT, eye).diffuse.x, c.expected, 1e-6)
      << c.c.x << " " << c.c.y << " " << c.c.z;
  }
}

TEST(Attenuation, DirectionalLightsDoNotAttenuate)
{
  glsl::slLight light = directionalFrom(kUp);
  light.attenuation = glm::vec3(0.0f, 0.0f, 100.0f);
  light.position = glm::vec3(0.0f, 0.0f, 1000.0f);
  EXPECT_NEAR(shadeOne(light, unitMaterial(1), 0, glm::vec3(0, 0, 5)).diffuse.x, 1.0, 1e-6);
}

namespace
{
/// Diffuse at a floor point seen from a spot light 1 unit above the origin
/// pointing straight down, for a point at @p degrees off the spot axis.
double spotAt(const glsl::slLight& spot, double degrees)
{
  const glm::vec3 point(static_cast<float>(std::tan(radians(degrees))), 0.0f, 0.0f);
  glsl::slLight l = spot;
  l.position = glm::vec3(0.0f, 0.0f, 1.0f);
  l.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  return shadeOne(l, unitMaterial(1), glsl::SL_MODEL_LAMBERT, glm::vec3(0, 0, 5), point).diffuse.x;
}

double smoothstep(double e0, double e1, double x)
{
  const double t = std::min(1.0, std::max(0.0, (x - e0) / (e1 - e0)));
  return t * t * (3.0 - 2.0 * t);
}
} // namespace

TEST(Spot, InsideAtTheEdgeAndOutside)
{
  glsl::slLight spot = whiteLight(glsl::SL_LIGHT_SPOT);
  spot.cosCutoff = static_cast<float>(std::cos(radians(30.0)));
  spot.cosInner = spot.cosCutoff;
  spot.exponent = 2.0f;
  // On the floor at angle a the light is 1/cos a away and hits at angle a:
  // diffuse = cos a (Lambert) * cos^2 a (spot exponent), no attenuation.
  for (double a : { 0.0, 15.0, 29.9 })
  {
    EXPECT_NEAR(spotAt(spot, a), std::pow(std::cos(radians(a)), 3.0), 1e-5) << a;
  }
  EXPECT_EQ(spotAt(spot, 30.1), 0.0);
  EXPECT_EQ(spotAt(spot, 60.0), 0.0);
}

TEST(Spot, SmoothEdgeFadesAcrossTheBand)
{
  glsl::slLight spot = whiteLight(glsl::SL_LIGHT_SPOT);
  spot.cosCutoff = static_cast<float>(std::cos(radians(30.0)));
  spot.cosInner = static_cast<float>(std::cos(radians(20.0)));
  spot.exponent = 0.0f;
  EXPECT_NEAR(spotAt(spot, 10.0), std::cos(radians(10.0)), 1e-5); // inside the inner cone: full
  for (double a : { 21.0, 25.0, 29.0 })
  {
    const double edge = smoothstep(std::cos(radians(30.0)), std::cos(radians(20.0)), std::cos(radians(a)));
    EXPECT_NEAR(spotAt(spot, a), edge * std::cos(radians(a)), 1e-4) << a;
  }
  EXPECT_LT(spotAt(spot, 29.0), spotAt(spot, 25.0));
  EXPECT_EQ(spotAt(spot, 31.0), 0.0);
}

TEST(Emission, AddedOnceAndLightsNothingElse)
{
  const glsl::slLight light = directionalFrom(polar(radians(45.0)));
  glsl::slMaterial plain = unitMaterial(8);
  glsl::slMaterial glowing = plain;
  glowing.emission = glm::vec3(0.3f, 0.2f, 0.1f);
  const glm::vec3 eye = 10.0f * polar(radians(-10.0));
  const auto a = shadeOne(light, plain, glsl::SL_MODEL_BLINN_PHONG, eye);
  const auto b = shadeOne(light, glowing, glsl::SL_MODEL_BLINN_PHONG, eye);
  EXPECT_EQ(a.diffuse, b.diffuse);
  EXPECT_EQ(a.specular, b.specular);
  EXPECT_EQ(a.ambient, b.ambient);
  EXPECT_EQ(b.emission, glowing.emission);
  const glm::vec3 totalA = glsl::slTotal(a), totalB = glsl::slTotal(b);
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_NEAR(totalB[i] - totalA[i], glowing.emission[i], 1e-6);
  }
  // With no light at all, emission is all there is, added exactly once.
  const auto dark = shadePoint({}, glowing, glsl::SL_MODEL_PHONG, kOrigin, kUp, eye);
  EXPECT_EQ(glsl::slTotal(dark), glowing.emission);
  // Several lights still add emission once.
  const auto many = shadePoint({ light, light, light }, glowing, glsl::SL_MODEL_PHONG, kOrigin, kUp, eye);
  EXPECT_EQ(many.emission, glowing.emission);
}

TEST(Ambient, AmbientLightTimesKa)
{
  glsl::slLight ambient = whiteLight(glsl::SL_LIGHT_AMBIENT);
  ambient.ambient = glm::vec3(0.5f, 0.25f, 1.0f);
  ambient.intensity = 2.0f;
  glsl::slMaterial m = unitMaterial(1);
  m.ambient = glm::vec3(0.2f, 0.4f, 0.1f);
  // Independent of the normal, even a normal facing away.
  const auto t = shadeOne(ambient, m, glsl::SL_MODEL_PHONG, glm::vec3(0, 0, 5), kOrigin, -kUp);
  EXPECT_NEAR(t.ambient.x, 2.0 * 0.5 * 0.2, 1e-6);
  EXPECT_NEAR(t.ambient.y, 2.0 * 0.25 * 0.4, 1e-6);
  EXPECT_NEAR(t.ambient.z, 2.0 * 1.0 * 0.1, 1e-6);
  EXPECT_EQ(t.diffuse, glm::vec3(0.0f));
}

TEST(Ambient, PerLightAmbientIsAttenuatedLikeTheLight)
{
  glsl::slLight light = whiteLight(glsl::SL_LIGHT_POINT);
  light.position = glm::vec3(0.0f, 0.0f, 2.0f);
  light.ambient = glm::vec3(1.0f);
  light.attenuation = glm::vec3(0.0f, 0.0f, 1.0f); // 1/d^2 = 1/4
  glsl::slMaterial m = unitMaterial(1);
  m.ambient = glm::vec3(0.5f);
  EXPECT_NEAR(shadeOne(light, m, 0, glm::vec3(0, 0, 5)).ambient.x, 0.5 / 4.0, 1e-6);
}

TEST(Luminance, IsTheRec709Weighting)
{
  // The published Rec. 709 / sRGB luminance weights (ITU-R BT.709-6, item
  // 3.3), which sum to 1, so a grey g has luminance g.
  EXPECT_NEAR(shadelab::glsl::slLuminance(glm::vec3(1, 0, 0)), 0.2126f, 1e-7f);
  EXPECT_NEAR(shadelab::glsl::slLuminance(glm::vec3(0, 1, 0)), 0.7152f, 1e-7f);
  EXPECT_NEAR(shadelab::glsl::slLuminance(glm::vec3(0, 0, 1)), 0.0722f, 1e-7f);
  EXPECT_NEAR(shadelab::glsl::slLuminance(glm::vec3(0.37f)), 0.37f, 1e-6f);
}

TEST(ColourProducts, FoldedLightShadesAsTheLightAndMaterial)
{
  // slFoldLight + slUnitMaterial (how the CPU kernel and the render pass
  // shade) against slShadeLightUnit with the light and material as given,
  // and the lecture's products written out here: intensity x light colour x
  // coefficient x weight, then the base colour on ambient and diffuse.
  glsl::slLight light = whiteLight(glsl::SL_LIGHT_POINT);
  light.position = glm::vec3(0.4f, -0.3f, 2.0f);
  light.ambient = glm::vec3(0.1f, 0.2f, 0.3f);
  light.diffuse = glm::vec3(0.9f, 0.5f, 0.2f);
  light.specular = glm::vec3(0.3f, 0.6f, 0.9f);
  light.intensity = 1.7f;
  light.attenuation = glm::vec3(0.5f, 0.1f, 0.2f);
  glsl::slMaterial m = unitMaterial(24.0f);
  m.ambient = glm::vec3(0.25f, 0.5f, 0.75f);
  m.diffuse = glm::vec3(0.6f, 0.3f, 0.15f);
  m.specular = glm::vec3(0.2f, 0.4f, 0.8f);
  m.emission = glm::vec3(0.05f);
  const glm::vec3 base(0.5f, 0.8f, 1.0f);
  const glm::vec3 P(0.1f, 0.0f, 0.0f), n = glm::normalize(glm::vec3(0.1f, 0.2f, 1.0f));
  const glm::vec3 v = glm::normalize(glm::vec3(-0.3f, 0.1f, 1.0f)), t(1.0f, 0.2f, -0.1f);
  for (int model = 0; model < kLightingModelCount; ++model)
  {
    const glsl::slTerms direct = glsl::slShadeLightUnit(light, m, model, P, n, t, v);
    const glsl::slTerms folded =
      glsl::slShadeLightUnit(glsl::slFoldLight(light, m), glsl::slUnitMaterial(m), model, P, n, t, v);
    const glsl::slLightWeights w = glsl::slLightWeightsAt(light, m, model, P, n, t, v);
    const glsl::slTerms coloured = glsl::slWithBaseColour(folded, base);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(folded.ambient[c], direct.ambient[c], 1e-6f * std::abs(direct.ambient[c]) + 1e-9f) << model;
      EXPECT_NEAR(folded.diffuse[c], direct.diffuse[c], 1e-6f * std::abs(direct.diffuse[c]) + 1e-9f) << model;
      EXPECT_NEAR(folded.specular[c], direct.specular[c], 1e-6f * std::abs(direct.specular[c]) + 1e-9f) << model;
      // w carries the intensity: w = intensity x reach x factor.
      EXPECT_NEAR(coloured.ambient[c], w.ambient * light.ambient[c] * m.ambient[c] * base[c], 1e-6) << model;
      EXPECT_NEAR(coloured.diffuse[c], w.diffuse * light.diffuse[c] * m.diffuse[c] * base[c], 1e-6) << model;
      EXPECT_NEAR(coloured.specular[c], w.specular * light.specular[c] * m.specular[c], 1e-6) << model;
    }
  }
}
