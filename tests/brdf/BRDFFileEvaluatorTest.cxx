// .brdf files evaluated on the GPU (slBRDFFileEvaluator): values, lobes
// and albedo of data/brdf/blinn-phong-normalized.brdf against the built-in
// model (slBRDF, directionalAlbedo); Ward's anisotropic file against the
// formula written here; shaders that do not compile or link.
#include "LightingTestUtilities.h"
#include "slBRDFFileEvaluator.h"
#include "slBRDFLobeSource.h"
#include "VTKErrors.h"

#include "shadelab/Albedo.h"
#include "shadelab/LightingGLSL.h"

#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

using namespace shadelab;
using shadelab::test::kPi;

namespace
{
const std::string kData = SHADELAB_DATA_DIR;

/// The message constructing an evaluator for @p text (written to a
/// temporary file @p name, removed again) throws, or "".
std::string compileError(const std::string& name, const std::string& text)
{
  const std::string path = testing::TempDir() + name;
  std::ofstream(path) << text;
  std::string message;
  try
  {
    const BrdfFile file = readBrdfFile(path);
    slBRDFFileEvaluator evaluator(file, brdfParameterValues(file, {}));
  }
  catch (const Error& e)
  {
    message = e.what();
  }
  std::remove(path.c_str());
  return message;
}

/// Directions over the upper hemisphere and a little below.
std::vector<glm::vec3> someDirections()
{
  std::vector<glm::vec3> out;
  for (int i = 0; i <= 12; ++i)
  {
    for (int j = 0; j < 24; ++j)
    {
      const double t = kPi * 0.5 * i / 12.0 * 0.999, p = 2.0 * kPi * j / 24.0;
      out.emplace_back(glm::dvec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)));
    }
  }
  return out;
}
} // namespace

TEST(BRDFFileEvaluator, BlinnPhongFileGivesTheBuiltInValues)
{
  const BrdfFile file = readBrdfFile(kData + "/brdf/blinn-phong-normalized.brdf");
  slBRDFFileEvaluator evaluator(file, brdfParameterValues(file, { "kd=0.3", "ks=0.7", "n=50" }));
  const glsl::slMaterial m = test::greyMaterial(0.3f, 0.7f, 50.0f);
  for (double degrees : { 0.0, 30.0, 60.0, 85.0 })
  {
    const double t = degrees * kPi / 180.0;
    const glm::vec3 L(glm::dvec3(-std::sin(t), 0.0, std::cos(t)));
    const std::vector<glm::vec3> V = someDirections();
    const std::vector<glm::vec3> f = evaluator.Evaluate(L, V);
    ASSERT_EQ(f.size(), V.size());
    for (size_t k = 0; k < V.size(); ++k)
    {
      const glm::vec3 expected = glsl::slBRDF(glsl::SL_MODEL_BLINN_PHONG_NORMALIZED, m, glm::vec3(0, 0, 1), glm::vec3(1, 0, 0), L, V[k]);
      EXPECT_NEAR(f[k].x, expected.x, 1e-4 * std::max(1.0f, expected.x)) << degrees << " degrees, direction " << k;
      EXPECT_EQ(f[k].x, f[k].y);
    }
  }
}

TEST(BRDFFileEvaluator, BlinnPhongFileGivesTheBuiltInLobe)
{
  const BrdfFile file = readBrdfFile(kData + "/brdf/blinn-phong-normalized.brdf");
  slBRDFFileEvaluator evaluator(file, brdfParameterValues(file, { "kd=0.3", "ks=0.7", "n=50" }));
  for (bool cosine : { false, true })
  {
    vtkNew<slBRDFLobeSource> builtIn, fromFile;
    for (slBRDFLobeSource* lobe : { builtIn.Get(), fromFile.Get() })
    {
      lobe->SetModel(glsl::SL_MODEL_BLINN_PHONG_NORMALIZED);
      lobe->SetDiffuseWeight(0.3);
      lobe->SetSpecularWeight(0.7);
      lobe->SetShininess(50.0);
      lobe->SetIncidenceAngle(40.0);
      lobe->SetMultiplyByCosine(cosine);
    }
    evaluator.SetLobeValues(fromFile);
    ASSERT_EQ(updateError(builtIn), "");
    ASSERT_EQ(updateError(fromFile), "");
    for (int port : { 0, 1 })
    {
      vtkDataArray* expected = builtIn->GetOutput(port)->GetPointData()->GetArray("BRDF");
      vtkDataArray* actual = fromFile->GetOutput(port)->GetPointData()->GetArray("BRDF");
      ASSERT_EQ(actual->GetNumberOfTuples(), expected->GetNumberOfTuples());
      double largest = 0.0;
      for (vtkIdType k = 0; k < expected->GetNumberOfTuples(); ++k)
      {
        const double e = expected->GetComponent(k, 0);
        largest = std::max(largest, std::abs(actual->GetComponent(k, 0) - e) / std::max(1.0, std::abs(e)));
        ASSERT_NEAR(actual->GetComponent(k, 0), e, 1e-4 * std::max(1.0, std::abs(e))) << "port " << port << " point " << k;
      }
      std::printf("lobe (port %d, cosine %d): largest relative difference %.1e\n", port, cosine, largest);
      // The same geometry: the points agree as the radii do.
      EXPECT_EQ(fromFile->GetOutput(port)->GetNumberOfCells(), builtIn->GetOutput(port)->GetNumberOfCells());
    }
  }
}

TEST(BRDFFileEvaluator, BlinnPhongFileGivesTheBuiltInAlbedo)
{
  const BrdfFile file = readBrdfFile(kData + "/brdf/blinn-phong-normalized.brdf");
  slBRDFFileEvaluator evaluator(file, brdfParameterValues(file, { "kd=0.3", "ks=0.7", "n=50" }));
  const glsl::slMaterial m = test::greyMaterial(0.3f, 0.7f, 50.0f);
  double largest = 0.0;
  for (double degrees : { 0.0, 20.0, 45.0, 70.0, 85.0, 89.0 })
  {
    const double t = degrees * kPi / 180.0;
    const double expected = directionalAlbedo(glsl::SL_MODEL_BLINN_PHONG_NORMALIZED, m, t);
    const double albedo = evaluator.AlbedoAtIncidence(degrees);
    largest = std::max(largest, std::abs(albedo - expected));
    EXPECT_NEAR(albedo, expected, 1e-4) << degrees << " degrees";
  }
  std::printf("albedo: largest difference from directionalAlbedo %.1e\n", largest);
}

TEST(BRDFFileEvaluator, WardFileMatchesTheFormulaWithItsParameters)
{
  // Ward's anisotropic BRDF written here: rho_d / pi + rho_s exp(-((H.X/ax)^2
  // + (H.Y/ay)^2) / (H.N)^2) / (4 pi ax ay sqrt(N.L N.V)).
  const BrdfFile file = readBrdfFile(kData + "/brdf/ward-anisotropic.brdf");
  auto ward = [](const glm::dvec3& rhoD, double rhoS, double ax, double ay, const glm::dvec3& L, const glm::dvec3& V) {
    const glm::dvec3 H = glm::normalize(L + V);
    const double e = (H.x / ax) * (H.x / ax) + (H.y / ay) * (H.y / ay);
    return rhoD / kPi + glm::dvec3(rhoS * std::exp(-e / (H.z * H.z)) / (4.0 * kPi * ax * ay * std::sqrt(L.z * V.z)));
  };
  const glm::dvec3 L = glm::normalize(glm::dvec3(-0.4, 0.2, 0.8));
  std::vector<glm::vec3> V;
  for (const glm::vec3& v : someDirections())
  {
    if (v.z > 0.05f)
    {
      V.push_back(v);
    }
  }
  for (bool isotropic : { false, true })
  {
    slBRDFFileEvaluator evaluator(file,
      brdfParameterValues(file, { "rho_d=0.2,0.4,0.6", "rho_s=0.5", "alpha_x=0.15", "alpha_y=0.35",
        isotropic ? "isotropic=1" : "isotropic=0" }));
    const std::vector<glm::vec3> f = evaluator.Evaluate(glm::vec3(L), V);
    for (size_t k = 0; k < V.size(); ++k)
    {
      const glm::dvec3 expected =
        ward(glm::dvec3(0.2, 0.4, 0.6), 0.5, 0.15, isotropic ? 0.15 : 0.35, L, glm::dvec3(V[k]));
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(f[k][c], expected[c], 1e-4 * std::max(1.0, expected[c])) << "direction " << k << " isotropic " << isotropic;
      }
    }
  }
}

TEST(BRDFFileEvaluator, ManyDirectionsTakeSeveralRenders)
{
  // More directions than one render holds (1024 x 1024): every value lands
  // in its place.
  const BrdfFile file = parseBrdfText("::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)\n"
                                      "{ return V + 2.0 * L; }\n::end shader\n", "echo.brdf");
  slBRDFFileEvaluator evaluator(file, {});
  std::vector<glm::vec3> V(1024 * 1024 + 3000);
  for (size_t k = 0; k < V.size(); ++k)
  {
    V[k] = glm::vec3(static_cast<float>(k % 1000), static_cast<float>(k / 1000), 0.5f);
  }
  const std::vector<glm::vec3> f = evaluator.Evaluate(glm::vec3(0.0f, 0.0f, 1.0f), V);
  for (size_t k = 0; k < V.size(); k += 997)
  {
    ASSERT_EQ(f[k], V[k] + glm::vec3(0.0f, 0.0f, 2.0f)) << k;
  }
  EXPECT_EQ(f.back(), V.back() + glm::vec3(0.0f, 0.0f, 2.0f));
}

TEST(BRDFFileEvaluator, ShaderThatDoesNotCompileNamesTheBrdfLine)
{
  const std::string path = kData + "/brdf/broken-glsl.brdf";
  const BrdfFile file = readBrdfFile(path);
  std::string message;
  try
  {
    slBRDFFileEvaluator evaluator(file, brdfParameterValues(file, {}));
  }
  catch (const Error& e)
  {
    message = e.what();
  }
  // "roughnes" (line 12 of the file) is undeclared; the message is the driver's.
  EXPECT_EQ(message.rfind(path + ":12: ", 0), 0u) << message;
  EXPECT_NE(message.find("roughnes"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  std::printf("%s\n", message.c_str());
}

TEST(BRDFFileEvaluator, OtherShaderErrorsAreOneLine)
{
  // Declared, never defined: the program does not link.
  const std::string undefined = compileError("undefined.brdf",
    "::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y);\n::end shader\n");
  EXPECT_EQ(undefined.rfind(testing::TempDir() + "undefined.brdf: ", 0), 0u) << undefined;
  EXPECT_EQ(undefined.find('\n'), std::string::npos) << undefined;
  // An error on the last line of the shader text.
  const std::string last = compileError("last.brdf",
    "analytic\n::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)\n{\n  return vec3(1.0)\n}\n::end shader\n");
  EXPECT_EQ(last.rfind(testing::TempDir() + "last.brdf:6: ", 0), 0u) << last;
  // A BRDF of the wrong type.
  const std::string type = compileError("type.brdf",
    "::begin shader\nfloat BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return 1.0; }\n::end shader\n");
  EXPECT_EQ(type.find('\n'), std::string::npos) << type;
  EXPECT_NE(type.rfind(testing::TempDir() + "type.brdf", 0), std::string::npos) << type;
  std::printf("%s\n%s\n%s\n", undefined.c_str(), last.c_str(), type.c_str());
}

TEST(BRDFFileEvaluator, AlbedoOfANonFiniteBRDFIsAnError)
{
  const BrdfFile file = parseBrdfText("::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)\n"
                                      "{ return vec3(1.0 / (V.x - V.x)); }\n::end shader\n", "inf.brdf");
  slBRDFFileEvaluator evaluator(file, {});
  std::string message;
  try
  {
    evaluator.Albedo(glm::dvec3(0.0, 0.0, 1.0));
  }
  catch (const Error& e)
  {
    message = e.what();
  }
  EXPECT_EQ(message, "inf.brdf: BRDF gives a value that is not finite at incidence 0 degrees: no albedo");
}

TEST(BRDFFileEvaluator, ParameterClashingWithTheEvaluationNamesItsLine)
{
  // "texCoord" is a name of the code around the shader: the uniform made
  // from the parameter on line 3 is a redeclaration.
  const std::string message = compileError("clash.brdf",
    "analytic\n::begin parameters\nfloat texCoord 0 1 0.5\n::end parameters\n::begin shader\n"
    "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec3(texCoord); }\n::end shader\n");
  EXPECT_EQ(message.rfind(testing::TempDir() + "clash.brdf:3: ", 0), 0u) << message;
  EXPECT_NE(message.find("(the uniform of parameter \"texCoord\")"), std::string::npos) << message;
  std::printf("%s\n", message.c_str());
}
