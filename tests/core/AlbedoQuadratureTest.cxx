// The fixed albedo quadrature (the rule a .brdf BRDF's albedo is computed
// with on the GPU) against shadelab::directionalAlbedo (adaptive
// Gauss-Kronrod to 1e-9) and against closed forms, with f_r from slBRDF()
// evaluated here at the rule's nodes.
#include "LightingTestUtilities.h"

#include "shadelab/Albedo.h"
#include "shadelab/AlbedoQuadrature.h"
#include "shadelab/LightingGLSL.h"
#include "shadelab/LightingGLSLDouble.h"
#include "shadelab/Scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace shadelab;
using shadelab::test::kPi;

namespace
{

/// The rule's albedo for the built-in @p model, f_r from slBRDF at its
/// nodes: in double (the rule's own error) or in float with the nodes as
/// float, as a GPU evaluates them.
double ruleAlbedo(int model, const glsl::slMaterial& m, double thetaI, double azimuth = 0.0, bool inFloat = false)
{
  const glm::dvec3 L(std::sin(thetaI) * std::cos(azimuth), std::sin(thetaI) * std::sin(azimuth), std::cos(thetaI));
  const AlbedoQuadrature rule = albedoQuadrature(L);
  glsld::slMaterial md;
#define SHADELAB_COPY(type, field, ...) md.field = m.field;
  SHADELAB_MATERIAL_PARAMETERS(SHADELAB_COPY)
#undef SHADELAB_COPY
  // N = +z and the tangent X = +x, as directionalAlbedo() takes them.
  std::vector<glm::vec3> f;
  for (const glm::dvec3& V : rule.directions)
  {
    f.push_back(inFloat
        ? glsl::slBRDF(model, m, glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(L), glm::vec3(V))
        : glm::vec3(glsld::slBRDF(model, md, glm::dvec3(0.0, 0.0, 1.0), glm::dvec3(1.0, 0.0, 0.0), L, V)));
  }
  return albedoFromValues(rule, f);
}
} // namespace

TEST(AlbedoQuadrature, LambertIsExactlyRho)
{
  // f_r = rho / pi: the albedo is rho at every incidence.
  for (double degrees : { 0.0, 30.0, 60.0, 85.0, 89.9 })
  {
    EXPECT_NEAR(ruleAlbedo(glsl::SL_MODEL_LAMBERT_NORMALIZED, test::greyMaterial(0.8f, 0.0f, 1.0f), degrees * kPi / 180.0),
      0.8, 1e-7)
      << degrees;
  }
}

TEST(AlbedoQuadrature, MatchesTheAdaptiveAlbedoOfSpecularLobes)
{
  // The rule's own error (f_r in double) and the error with f_r and the
  // nodes in float, as the GPU evaluates a .brdf file.
  struct Case
  {
    int model;
    float n;
    double tolerance, floatTolerance;
  };
  const Case cases[] = {
    { glsl::SL_MODEL_BLINN_PHONG_NORMALIZED, 50.0f, 1e-8, 2e-6 },
    { glsl::SL_MODEL_PHONG_NORMALIZED, 50.0f, 1e-8, 2e-6 },
    { glsl::SL_MODEL_BLINN_PHONG_NORMALIZED, 1000.0f, 1e-8, 3e-5 },
    { glsl::SL_MODEL_PHONG_NORMALIZED, 1000.0f, 1e-8, 3e-5 },
    { glsl::SL_MODEL_BLINN_PHONG_NORMALIZED, 10000.0f, 2e-6, 3e-4 },
  };
  for (const Case& c : cases)
  {
    const glsl::slMaterial m = test::greyMaterial(0.3f, 0.7f, c.n);
    double worst = 0.0, worstFloat = 0.0;
    for (double degrees : { 0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.0 })
    {
      const double thetaI = degrees * kPi / 180.0;
      const double expected = directionalAlbedo(c.model, m, thetaI);
      const double error = std::abs(ruleAlbedo(c.model, m, thetaI) - expected);
      const double floatError = std::abs(ruleAlbedo(c.model, m, thetaI, 0.0, true) - expected);
      worst = std::max(worst, error);
      worstFloat = std::max(worstFloat, floatError);
      EXPECT_LT(error, c.tolerance) << "model " << c.model << " n " << c.n << " at " << degrees << " degrees";
      EXPECT_LT(floatError, c.floatTolerance) << "model " << c.model << " n " << c.n << " at " << degrees << " degrees, float";
    }
    std::printf("model %d n %g: largest difference from directionalAlbedo %.1e (double), %.1e (float)\n", c.model,
      static_cast<double>(c.n), worst, worstFloat);
  }
  std::printf("nodes at 45 degrees: %zu\n", albedoQuadrature(glm::dvec3(0.7071, 0.0, 0.7071)).directions.size());
}

TEST(AlbedoQuadrature, MatchesTheAdaptiveAlbedoOfEveryModel)
{
  // Every row of the model table with the scene format's default roughness
  // (microfacet, Oren-Nayar and anisotropic lobes included), relative to
  // the value (the lecture models grow large toward grazing incidence).
  for (int model : test::allModels())
  {
    const glsl::slMaterial m = test::greyMaterial(0.3f, 0.7f, 50.0f);
    double worst = 0.0;
    for (double degrees : { 0.0, 30.0, 60.0, 85.0 })
    {
      const double thetaI = degrees * kPi / 180.0;
      const double expected = directionalAlbedo(model, m, thetaI);
      const double error = std::abs(ruleAlbedo(model, m, thetaI) - expected) / std::max(1.0, std::abs(expected));
      worst = std::max(worst, error);
      EXPECT_LT(error, 1e-7) << modelName(static_cast<ShadingModel>(model)) << " at " << degrees << " degrees";
    }
    std::printf("%s: largest relative difference %.1e\n", modelName(static_cast<ShadingModel>(model)), worst);
  }
}

TEST(AlbedoQuadrature, DoesNotDependOnTheLightsAzimuth)
{
  // An isotropic BRDF: turning the light about the normal changes nothing.
  const glsl::slMaterial m = test::greyMaterial(0.2f, 0.8f, 50.0f);
  const double a = ruleAlbedo(glsl::SL_MODEL_BLINN_PHONG_NORMALIZED, m, 1.0, 0.0);
  EXPECT_NEAR(ruleAlbedo(glsl::SL_MODEL_BLINN_PHONG_NORMALIZED, m, 1.0, 2.0), a, 1e-7);
}

TEST(AlbedoQuadrature, NonFiniteValuesGiveNaN)
{
  const AlbedoQuadrature rule = albedoQuadrature(glm::dvec3(0.0, 0.0, 1.0));
  std::vector<glm::vec3> f(rule.directions.size(), glm::vec3(1.0f));
  EXPECT_NEAR(albedoFromValues(rule, f), kPi, 1e-9);
  f[5].y = std::nanf("");
  EXPECT_TRUE(std::isnan(albedoFromValues(rule, f)));
}
