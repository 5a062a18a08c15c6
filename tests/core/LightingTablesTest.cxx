// The tables of LightingTables.h against what is derived from them: the
// generated GLSL constants and slIsNormalizedModel(), the name lists, the
// formulas of slLighting.glsl (every model and light type row must have its
// expected values in TableExpectations.h, and the "reads" and "lobe" columns
// must say what the formulas do).
#include "TableExpectations.h"

#include "shadelab/LightingTables.h"
#include "shadelab/Scene.h"

#include <gtest/gtest.h>

#include <cctype>
#include <tuple>

using namespace shadelab;
using namespace shadelab::test;

TEST(LightingTables, GeneratedConstantsAreTheRowPositions)
{
#define SHADELAB_CHECK(Enumerator, GLSL, ...)                                                                         \
  EXPECT_EQ(glsl::SL_MODEL_##GLSL, static_cast<int>(ShadingModel::Enumerator));
  SHADELAB_LIGHTING_MODELS(SHADELAB_CHECK)
#undef SHADELAB_CHECK
#define SHADELAB_CHECK(Enumerator, GLSL, ...) EXPECT_EQ(glsl::SL_LIGHT_##GLSL, static_cast<int>(LightType::Enumerator));
  SHADELAB_LIGHT_TYPES(SHADELAB_CHECK)
#undef SHADELAB_CHECK
  EXPECT_EQ(glsl::SL_MODEL_COUNT, kLightingModelCount);
  EXPECT_EQ(glsl::SL_LIGHT_TYPE_COUNT, kLightTypeCount);
  for (int i = 0; i < kLightingModelCount; ++i)
  {
    EXPECT_EQ(static_cast<int>(kLightingModels[i].model), i);
  }
  for (int i = 0; i < kLightTypeCount; ++i)
  {
    EXPECT_EQ(static_cast<int>(kLightTypes[i].type), i);
  }
}

TEST(LightingTables, NormalizedColumnIsTheGLSLTest)
{
  for (const LightingModelInfo& m : kLightingModels)
  {
    EXPECT_EQ(glsl::slIsNormalizedModel(static_cast<int>(m.model)), m.normalized) << m.name;
  }
  EXPECT_FALSE(glsl::slIsNormalizedModel(kLightingModelCount));
  EXPECT_FALSE(glsl::slIsNormalizedModel(-1));
}

namespace
{
/// Each row's name is its enum value's name, parses back to it, and its
/// value is no problem; the name list has one entry per row.
template <typename Row, size_t N, typename Enum>
void expectNamesAreTheRows(const Row (&rows)[N], Enum Row::*value, const std::vector<std::string>& names,
  const char* (*nameOf)(Enum), bool (*parse)(const std::string&, Enum&), std::string (*problem)(int))
{
  ASSERT_EQ(names.size(), N);
  for (const Row& row : rows)
  {
    EXPECT_STREQ(nameOf(row.*value), row.name);
    Enum parsed{};
    ASSERT_TRUE(parse(row.name, parsed)) << row.name;
    EXPECT_EQ(parsed, row.*value);
    EXPECT_EQ(problem(static_cast<int>(row.*value)), "");
  }
}
} // namespace

TEST(LightingTables, NamesComeFromTheRows)
{
  expectNamesAreTheRows(
    kLightingModels, &LightingModelInfo::model, modelNames(), &modelName, &parseModelName, &modelValueProblem);
  expectNamesAreTheRows(
    kLightTypes, &LightTypeInfo::type, lightTypeNames(), &lightTypeName, &parseLightTypeName, &lightTypeValueProblem);
}

TEST(LightingTables, ValuesOutsideTheTablesAreNamedAsSuch)
{
  EXPECT_STREQ(modelName(static_cast<ShadingModel>(kLightingModelCount)),
    ("(unknown lighting model " + std::to_string(kLightingModelCount) + ")").c_str());
  EXPECT_STREQ(modelName(static_cast<ShadingModel>(-1)), "(unknown lighting model -1)");
  EXPECT_STREQ(lightTypeName(static_cast<LightType>(kLightTypeCount)),
    ("(unknown light type " + std::to_string(kLightTypeCount) + ")").c_str());
  const std::string problem = modelValueProblem(kLightingModelCount);
  EXPECT_EQ(problem.rfind(std::to_string(kLightingModelCount) + " is not a lighting model (0 lambert, 1 phong", 0), 0u)
    << problem;
  EXPECT_NE(lightTypeValueProblem(-1).find("-1 is not a light type (0 directional"), std::string::npos);
  EXPECT_FALSE(isLightingModel(kLightingModelCount));
  EXPECT_FALSE(isLightType(-1));
}

namespace
{
/// Fixed geometries over the hemisphere: light and eye at several angles,
/// in and out of the plane of incidence, and a light behind the surface.
std::vector<ReflectionGeometry> geometries()
{
  std::vector<ReflectionGeometry> out;
  const glm::dvec3 N(0.0, 0.0, 1.0);
  for (double lightDegrees : { 0.0, 25.0, 60.0, 100.0 })
  {
    for (const auto& eye : { std::make_pair(0.0, 0.0), std::make_pair(30.0, 180.0), std::make_pair(45.0, 90.0),
           std::make_pair(70.0, 200.0) })
    {
      // A wide, a middling and a narrow lobe of each kind; the tangent at 30
      // degrees from the plane of incidence, so the anisotropic lobes are
      // not symmetric about it.
      for (const auto& lobe : { std::make_tuple(1.0, 0.8, 0.9, 2.5), std::make_tuple(8.0, 0.3, 0.2, 1.5),
             std::make_tuple(50.0, 0.1, 0.05, 1.33) })
      {
        const double alpha = std::get<1>(lobe), alphaX = std::get<2>(lobe);
        out.push_back({ N, glm::dvec3(polar(radians(lightDegrees))),
          glm::dvec3(polar(radians(eye.first), radians(eye.second))), std::get<0>(lobe),
          glm::dvec3(polar(radians(90.0), radians(30.0))), alpha, alphaX, std::min(1.0, 2.5 * alphaX),
          std::get<3>(lobe) });
      }
    }
  }
  return out;
}
} // namespace

TEST(LightingTables, EveryModelComputesItsExpectedValues)
{
  for (const LightingModelInfo& m : kLightingModels)
  {
    const auto expected = modelExpectations().find(m.name);
    ASSERT_NE(expected, modelExpectations().end()) << m.name << " has no expected values in TableExpectations.h";
    for (const ReflectionGeometry& g : geometries())
    {
      const ReflectionFactors want = expected->second(g);
      const int model = static_cast<int>(m.model);
      const glm::vec3 N(g.N), L(g.L), V(g.V), X(g.X);
      glsl::slMaterial mat = unitMaterial(static_cast<float>(g.n));
      mat.roughness = static_cast<float>(g.alpha);
      mat.roughnessX = static_cast<float>(g.alphaX);
      mat.roughnessY = static_cast<float>(g.alphaY);
      mat.ior = static_cast<float>(g.ior);
      const double diffuse = glsl::slDiffuseFactor(model, mat, N, L, V);
      const double specular = glsl::slSpecularFactor(model, mat, N, X, L, V);
      EXPECT_NEAR(diffuse, want.diffuse, 1e-5 * want.diffuse + 1e-7) << m.name;
      EXPECT_NEAR(specular, want.specular, 1e-4 * want.specular + 1e-6)
        << m.name << " n " << g.n << " alpha " << g.alpha << " L " << g.L.x << " " << g.L.z << " V " << g.V.x << " "
        << g.V.y << " " << g.V.z;
    }
  }
  EXPECT_EQ(modelExpectations().size(), static_cast<size_t>(kLightingModelCount)) << "an expectation names no model";
}

TEST(LightingTables, ReadsColumnIsWhatTheFormulaReads)
{
  // Light at 30 degrees, eye 10 degrees off the mirror direction, a light
  // with every colour: each material parameter a model reads changes its
  // result there, each one it does not read leaves it alone.
  slLight light = directionalFrom(polar(radians(30.0)));
  light.ambient = glm::vec3(0.3f);
  const glm::vec3 P(0.0f), N(0.0f, 0.0f, 1.0f), X(1.0f, 0.0f, 0.0f), eye = 5.0f * polar(radians(-20.0), 0.5);
  glsl::slMaterial base = unitMaterial(10.0f);
  base.ambient = glm::vec3(0.5f);
  base.emission = glm::vec3(0.25f);
  auto total = [&](int model, const glsl::slMaterial& m) {
    return glsl::slTotal(glsl::slAddEmission(glsl::slShadeLight(light, m, model, P, N, X, eye), m)).x;
  };
  for (const LightingModelInfo& info : kLightingModels)
  {
    const int model = static_cast<int>(info.model);
    const float before = total(model, base);
    auto check = [&](unsigned bit, const char* what, const glsl::slMaterial& changed) {
      EXPECT_EQ(total(model, changed) != before, (info.reads & bit) != 0) << info.name << " and " << what;
    };
#define SHADELAB_CHANGE(type, field, bit, ...)                                                                     \
  {                                                                                                                   \
    glsl::slMaterial changed = base;                                                                                  \
    changed.field = changed.field * 2.0f;                                                                             \
    check(bit, #field, changed);                                                                                      \
  }
    SHADELAB_MATERIAL_PARAMETERS(SHADELAB_CHANGE)
#undef SHADELAB_CHANGE
  }
}

TEST(LightingTables, LobeColumnIsTheSpecularLobesShape)
{
  // Light along the normal, eye at 60 degrees: R.V = cos 60 around the
  // mirror direction, N.H = cos 30 around the normal in H. The specular
  // factor relative to the eye on the normal shows which.
  const glm::vec3 N(0.0f, 0.0f, 1.0f), L = N, X(1.0f, 0.0f, 0.0f);
  const float n = 6.0f;
  const glsl::slMaterial mat = unitMaterial(n);
  for (const LightingModelInfo& m : kLightingModels)
  {
    const int model = static_cast<int>(m.model);
    const double onAxis = glsl::slSpecularFactor(model, mat, N, X, L, N);
    const double off = glsl::slSpecularFactor(model, mat, N, X, L, polar(radians(60.0)));
    switch (m.lobe)
    {
      case SpecularLobe::None:
        EXPECT_EQ(onAxis, 0.0) << m.name;
        EXPECT_EQ(off, 0.0) << m.name;
        break;
      case SpecularLobe::Mirror:
        EXPECT_NEAR(off / onAxis, std::pow(std::cos(radians(60.0)), n), 1e-5) << m.name;
        break;
      case SpecularLobe::Halfway:
        EXPECT_NEAR(off / onAxis, std::pow(std::cos(radians(30.0)), n), 1e-5) << m.name;
        break;
      case SpecularLobe::GGX:
      case SpecularLobe::Beckmann:
      case SpecularLobe::Ward:
      case SpecularLobe::AshikhminShirley:
        // A distribution of H: its peak is at H = N (the mirror direction).
        EXPECT_GT(onAxis, 0.0) << m.name;
        EXPECT_LT(off, 0.5 * onAxis) << m.name;
        break;
    }
  }
}

TEST(LightingTables, EveryLightTypeArrivesAsExpected)
{
  for (const LightTypeInfo& t : kLightTypes)
  {
    const auto expected = lightTypeExpectations().find(t.name);
    ASSERT_NE(expected, lightTypeExpectations().end()) << t.name << " has no expected values in TableExpectations.h";
    const slLight light = expectationLight(static_cast<int>(t.type));
    for (const glm::dvec3& P : { glm::dvec3(0.0), glm::dvec3(1.0, 0.5, 0.0), glm::dvec3(2.2, 0.0, 0.5),
           glm::dvec3(-1.5, 1.0, -1.0), glm::dvec3(5.0, 0.0, 0.0) })
    {
      const ExpectedIncidence want = expected->second(P);
      const glsl::slIncidence got = glsl::slIncidenceAt(light, glm::vec3(P));
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(got.L[c], want.L[c], 1e-6) << t.name;
      }
      EXPECT_NEAR(got.reach, want.reach, 1e-5) << t.name << " at " << P.x << " " << P.y << " " << P.z;
    }
  }
  EXPECT_EQ(lightTypeExpectations().size(), static_cast<size_t>(kLightTypeCount)) << "an expectation names no type";
}

TEST(LightingTables, LightsWithoutDiffuseLightOnlyTheAmbientTerm)
{
  // The parameters column: a type that takes no diffuse and specular colours
  // contributes only through k_a.
  for (const LightTypeInfo& t : kLightTypes)
  {
    slLight light = expectationLight(static_cast<int>(t.type));
    light.ambient = glm::vec3(0.5f);
    const glsl::slTerms terms = glsl::slShadeLight(light, unitMaterial(4.0f), glsl::SL_MODEL_PHONG,
      glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 5.0f));
    const bool lit = terms.diffuse.x > 0.0f || terms.specular.x > 0.0f;
    EXPECT_EQ(lit, (t.parameters & kLightDiffuse) != 0) << t.name;
  }
}
