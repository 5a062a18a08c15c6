// BRDF Explorer .brdf files: what the reader takes, what it rejects (one
// line naming file, line and reason), parameter values and overrides, the
// uniform declarations and the driver's compile log turned into a .brdf line.
#include "shadelab/BrdfFile.h"
#include "shadelab/Error.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

using namespace shadelab;

namespace
{
const std::string kData = SHADELAB_DATA_DIR;

/// The message parseBrdfText() throws for @p text, or "" if it parses.
std::string errorFor(const std::string& text)
{
  try
  {
    parseBrdfText(text, "bad.brdf");
  }
  catch (const Error& e)
  {
    return e.what();
  }
  return "";
}

const std::string kShader = "::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec3(1.0); }\n"
                            "::end shader\n";

/// A file with @p parameterLines as its parameter block (from line 2).
std::string withParameters(const std::string& parameterLines)
{
  return "::begin parameters\n" + parameterLines + "::end parameters\n" + kShader;
}

std::string overrideError(const BrdfFile& file, const std::vector<std::string>& overrides)
{
  try
  {
    brdfParameterValues(file, overrides);
  }
  catch (const Error& e)
  {
    return e.what();
  }
  return "";
}
} // namespace

TEST(BrdfFile, ReadsTheBlinnPhongFile)
{
  const BrdfFile file = readBrdfFile(kData + "/brdf/blinn-phong-normalized.brdf");
  ASSERT_EQ(file.parameters.size(), 3u);
  EXPECT_EQ(file.parameters[0].name, "kd");
  EXPECT_EQ(file.parameters[2].name, "n");
  EXPECT_EQ(file.parameters[2].kind, BrdfParameter::Kind::Float);
  EXPECT_EQ(file.parameters[2].minimum, 1.0f);
  EXPECT_EQ(file.parameters[2].maximum, 1000.0f);
  EXPECT_EQ(file.parameters[2].defaultValue.x, 50.0f);
  EXPECT_EQ(file.parameters[0].line, 11);
  // The shader's first line is the one after "::begin shader" (line 16).
  EXPECT_EQ(file.shaderFirstLine, 17);
  EXPECT_EQ(file.shader.substr(0, 1), "\n");
  EXPECT_NE(file.shader.find("vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)"), std::string::npos);
  EXPECT_EQ(file.shader.find("::end"), std::string::npos);
}

TEST(BrdfFile, ReadsEveryParameterKind)
{
  const BrdfFile file = readBrdfFile(kData + "/brdf/ward-anisotropic.brdf");
  ASSERT_EQ(file.parameters.size(), 5u);
  EXPECT_EQ(file.parameters[0].kind, BrdfParameter::Kind::Color);
  EXPECT_EQ(file.parameters[0].defaultValue, glm::vec3(0.3f, 0.15f, 0.05f));
  EXPECT_EQ(file.parameters[4].kind, BrdfParameter::Kind::Bool);
  EXPECT_EQ(file.parameters[4].defaultValue.x, 0.0f);
  EXPECT_EQ(brdfUniformDeclarations(file),
    "uniform vec3 rho_d;\nuniform float rho_s;\nuniform float alpha_x;\nuniform float alpha_y;\n"
    "uniform bool isotropic;\n");
}

TEST(BrdfFile, ReadsCrlfLineEnds)
{
  const BrdfFile file = readBrdfFile(kData + "/brdf/lambert-crlf.brdf");
  ASSERT_EQ(file.parameters.size(), 1u);
  EXPECT_EQ(file.parameters[0].name, "albedo");
  EXPECT_EQ(file.parameters[0].defaultValue, glm::vec3(0.8f));
  EXPECT_EQ(file.shaderFirstLine, 7);
  EXPECT_EQ(file.shader.find('\r'), std::string::npos);
}

TEST(BrdfFile, TakesCommentsBlankLinesAndNoParameters)
{
  const BrdfFile file = parseBrdfText("# only a shader\n\n  analytic  \n\n" + kShader, "a.brdf");
  EXPECT_TRUE(file.parameters.empty());
  EXPECT_EQ(file.shaderFirstLine, 6);
  EXPECT_EQ(brdfUniformDeclarations(file), "");
  // A bool written true/false, signs and exponents, a comment after a value.
  const BrdfFile other = parseBrdfText(
    withParameters("bool on true\nfloat a -1e-1 +2.5e1 .5 # half\ncolor c 0 +1 1.\n"), "b.brdf");
  EXPECT_EQ(other.parameters[0].defaultValue.x, 1.0f);
  EXPECT_FLOAT_EQ(other.parameters[1].minimum, -0.1f);
  EXPECT_FLOAT_EQ(other.parameters[1].maximum, 25.0f);
  EXPECT_FLOAT_EQ(other.parameters[1].defaultValue.x, 0.5f);
  EXPECT_EQ(other.parameters[2].defaultValue, glm::vec3(0.0f, 1.0f, 1.0f));
}

TEST(BrdfFile, ParametersMayTakeAnyNameButBRDFsArguments)
{
  // L, V and N are free here: this BRDF names its arguments otherwise, and
  // the L of another function, of a call or of a comment hides nothing.
  const BrdfFile file = parseBrdfText("::begin parameters\nfloat L 0 1 0.5\ncolor N 0 0 1\nbool V 1\n"
                                      "::end parameters\n::begin shader\n"
                                      "float f(float L) { return L; }\n"
                                      "vec3 BRDF(vec3 l, vec3 v, vec3 n, vec3 x, vec3 y); // vec3 BRDF(vec3 L) {\n"
                                      "vec3 BRDF(vec3 l, vec3 v, vec3 n, vec3 x, vec3 y)\n"
                                      "{ return N * f(L) * (V ? 1.0 : 0.0); }\n::end shader\n",
    "free.brdf");
  ASSERT_EQ(file.parameters.size(), 3u);
  EXPECT_EQ(file.parameters[0].name, "L");
}

TEST(BrdfFile, RejectsBadFilesWithOneLine)
{
  const std::pair<std::string, std::string> cases[] = {
    { "", "bad.brdf: the file is empty" },
    { "analytic\n", "bad.brdf: no shader block (::begin shader ... ::end shader)" },
    { "measured\n" + kShader,
      "bad.brdf:1: unexpected text \"measured\" outside the blocks (the file holds \"analytic\", # comments, "
      "a parameters and a shader block)" },
    { kShader + "analytic\n", "bad.brdf:4: \"analytic\" may only be the first line" },
    { "::begin reflectanceShader\n", "bad.brdf:1: unknown block \"reflectanceShader\" (parameters or shader)" },
    { "::end shader\n", "bad.brdf:1: \"::end shader\" without its ::begin" },
    { kShader + kShader, "bad.brdf:4: a second shader block" },
    { "::begin shader\nvec3 BRDF(vec3 L) { return L; }\n",
      "bad.brdf:1: ::begin shader has no ::end shader (the file ends on line 2)" },
    { "::begin shader\nvec3 BRDF(vec3 L) { return L; }\n::begin parameters\n::end parameters\n",
      "bad.brdf:3: \"::begin parameters\" inside the shader block (::begin shader on line 1 has no ::end "
      "shader before it)" },
    { "::begin parameters\nfloat a 0 1 0\n" + kShader,
      "bad.brdf:3: \"::begin shader\" inside the parameter block (::begin parameters on line 1 has no ::end "
      "parameters before it)" },
    { "::begin shader\nvec3 brdf(vec3 L) { return L; }\n::end shader\n",
      "bad.brdf:1: the shader block does not define vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)" },
    { withParameters("int a 0 1 0\n"), "bad.brdf:2: unknown parameter type \"int\" (float, bool or color)" },
    { withParameters("float a 0 1\n"), "bad.brdf:2: float needs 4 values (float NAME MIN MAX DEFAULT), the line has 3" },
    { withParameters("bool a\n"), "bad.brdf:2: bool needs 2 values (bool NAME DEFAULT), the line has 1" },
    { withParameters("color a 1 1 1 1\n"), "bad.brdf:2: color needs 4 values (color NAME R G B), the line has 5" },
    { withParameters("float a 0 one 0\n"), "bad.brdf:2: a: maximum \"one\" is not a finite number" },
    { withParameters("float a 0 1 nan\n"), "bad.brdf:2: a: default \"nan\" is not a finite number" },
    { withParameters("float a 0 1e999 0\n"), "bad.brdf:2: a: maximum \"1e999\" is not a finite number" },
    { withParameters("float a 0 1 1f\n"), "bad.brdf:2: a: default \"1f\" is not a finite number" },
    { withParameters("float a 0 1 +-1\n"), "bad.brdf:2: a: default \"+-1\" is not a finite number" },
    { withParameters("float a 2 1 1.5\n"), "bad.brdf:2: a: the minimum 2 is above the maximum 1" },
    { withParameters("float a 0 1 2\n"), "bad.brdf:2: a: the default 2 is out of range [0, 1]" },
    { withParameters("bool a 2\n"), "bad.brdf:2: a: the default \"2\" is not a bool (0, 1, true or false)" },
    { withParameters("color c 1 x 1\n"), "bad.brdf:2: c: green \"x\" is not a finite number" },
    { withParameters("float 2a 0 1 0\n"),
      "bad.brdf:2: \"2a\" is not a GLSL name (letters, digits and _, not starting with a digit)" },
    { withParameters("float a-b 0 1 0\n"),
      "bad.brdf:2: \"a-b\" is not a GLSL name (letters, digits and _, not starting with a digit)" },
    { withParameters("float gl_x 0 1 0\n"), "bad.brdf:2: \"gl_x\" is a name GLSL reserves (gl_ prefix or __)" },
    { withParameters("float a__b 0 1 0\n"), "bad.brdf:2: \"a__b\" is a name GLSL reserves (gl_ prefix or __)" },
    { withParameters("float uniform 0 1 0\n"), "bad.brdf:2: \"uniform\" is a GLSL keyword" },
    { withParameters("float a 0 1 0\nbool a 1\n"), "bad.brdf:3: a second parameter named \"a\" (the first is on line 2)" },
    { withParameters("float a 0 1 0\ncolor N 0 0 1\n"),
      "bad.brdf:3: parameter \"N\" has the name of an argument of BRDF, which hides it there (rename it)" },
    { "::begin parameters\nfloat toLight 0 1 0\n::end parameters\n::begin shader\n"
      "float f(float L) { return L; } // vec3 BRDF(vec3 V) {\n"
      "vec3 BRDF(in vec3 toLight /* L */, vec3 V, vec3 N, vec3 X, const vec3 Y)\n{ return vec3(f(toLight.x)); }\n"
      "::end shader\n",
      "bad.brdf:2: parameter \"toLight\" has the name of an argument of BRDF, which hides it there (rename it)" },
    { "::begin parameters\n::end parameters\n::begin parameters\n",
      "bad.brdf:3: a second parameters block" },
    { std::string("analytic\n\x1b[31m\n"), "bad.brdf:2: control byte \\x1B in the text" },
    { std::string("analytic\n::begin shader\nvec3 BRDF() {\0}\n::end shader\n", 50),
      "bad.brdf:3: control byte \\x00 in the text" },
  };
  for (const auto& [text, message] : cases)
  {
    EXPECT_EQ(errorFor(text), message) << text;
  }
}

TEST(BrdfFile, NamesAMissingOrUnreadableFile)
{
  EXPECT_THROW(
    {
      try
      {
        readBrdfFile("/nonexistent/none.brdf");
      }
      catch (const Error& e)
      {
        EXPECT_STREQ(e.what(), "/nonexistent/none.brdf: cannot open BRDF file: No such file or directory");
        throw;
      }
    },
    Error);
}

TEST(BrdfFile, ParameterValuesTakeOverrides)
{
  const BrdfFile file = readBrdfFile(kData + "/brdf/ward-anisotropic.brdf");
  std::vector<glm::vec3> values = brdfParameterValues(file, {});
  ASSERT_EQ(values.size(), 5u);
  EXPECT_EQ(values[0], glm::vec3(0.3f, 0.15f, 0.05f));
  EXPECT_EQ(values[3].x, 0.4f);
  values = brdfParameterValues(file, { "alpha_y=0.2", "isotropic=true", "rho_d=1, 0.5,0", "alpha_y=1" });
  EXPECT_EQ(values[3].x, 1.0f);
  EXPECT_EQ(values[4].x, 1.0f);
  EXPECT_EQ(values[0], glm::vec3(1.0f, 0.5f, 0.0f));
  EXPECT_EQ(brdfParameterValues(file, { "isotropic=0" })[4].x, 0.0f);
  // The range is closed.
  EXPECT_EQ(brdfParameterValues(file, { "alpha_x=0.01" })[2].x, 0.01f);
}

TEST(BrdfFile, RejectsBadOverrides)
{
  const BrdfFile file = readBrdfFile(kData + "/brdf/ward-anisotropic.brdf");
  const std::string f = kData + "/brdf/ward-anisotropic.brdf: --param ";
  EXPECT_EQ(overrideError(file, { "alpha_x" }), f + "\"alpha_x\": not NAME=VALUE");
  EXPECT_EQ(overrideError(file, { "n=3" }),
    f + "\"n=3\": the file has no parameter \"n\" (it has rho_d, rho_s, alpha_x, alpha_y, isotropic)");
  EXPECT_EQ(overrideError(file, { "alpha_x=2" }), f + "\"alpha_x=2\": alpha_x 2 is out of range [0.01, 1] (line 12)");
  EXPECT_EQ(overrideError(file, { "alpha_x=" }), f + "\"alpha_x=\": \"\" is not a finite number");
  EXPECT_EQ(overrideError(file, { "alpha_x=inf" }), f + "\"alpha_x=inf\": \"inf\" is not a finite number");
  EXPECT_EQ(overrideError(file, { "isotropic=yes" }),
    f + "\"isotropic=yes\": isotropic is a bool: \"yes\" is not 0, 1, true or false");
  EXPECT_EQ(overrideError(file, { "rho_d=1,1" }),
    f + "\"rho_d=1,1\": rho_d is a color: \"1,1\" is not three finite numbers R,G,B");
  EXPECT_EQ(overrideError(file, { "rho_d=1,1,1," }),
    f + "\"rho_d=1,1,1,\": rho_d is a color: \"1,1,1,\" is not three finite numbers R,G,B");
  const BrdfFile none = parseBrdfText(kShader, "none.brdf");
  EXPECT_EQ(overrideError(none, { "a=1" }), "none.brdf: --param \"a=1\": the file has no parameter \"a\" (it has none)");
}

TEST(BrdfFile, CompileErrorsNameTheBrdfLine)
{
  // The shader of broken-glsl.brdf starts on file line 9; the compiled
  // source puts it on line 30: source line 33 is file line 12.
  const BrdfFile file = readBrdfFile(kData + "/brdf/broken-glsl.brdf");
  ASSERT_EQ(file.shaderFirstLine, 9);
  const std::string path = kData + "/brdf/broken-glsl.brdf";
  // Mesa.
  EXPECT_EQ(brdfCompileError(file, "0:33(22): error: `roughnes' undeclared\n0:33(10): error: operands wrong\n", 30),
    path + ":12: `roughnes' undeclared");
  // glslang / AMD, after a warning line.
  EXPECT_EQ(brdfCompileError(file, "WARNING: 0:2: something\nERROR: 0:33: 'roughnes' : undeclared identifier\n", 30),
    path + ":12: 'roughnes' : undeclared identifier");
  // NVIDIA.
  EXPECT_EQ(brdfCompileError(file, "0(33) : error C1008: undefined variable \"roughnes\"\n", 30),
    path + ":12: undefined variable \"roughnes\"");
  // An error in the code around the file's text.
  EXPECT_EQ(brdfCompileError(file, "0:3(1): error: bad prelude\n", 30),
    path + ": bad prelude (line 3 of the compiled source, before the file's shader text)");
  EXPECT_EQ(brdfCompileError(file, "0:40(1): error: wrong type\n", 30),
    path + ": wrong type (line 40 of the compiled source, in the code that calls vec3 BRDF(vec3 L, vec3 V, vec3 N, "
           "vec3 X, vec3 Y))");
  // A linker's log has no line.
  EXPECT_EQ(brdfCompileError(file, "error: unresolved reference to function `BRDF'\n", 30),
    path + ": unresolved reference to function `BRDF'");
  // On the uniform declarations just before the shader text: the parameter's line.
  EXPECT_EQ(brdfCompileError(file, "0:29(1): error: redeclared\n", 30),
    path + ":5: redeclared (the uniform of parameter \"roughness\")");
  EXPECT_EQ(brdfCompileError(file, "something odd happened\n", 30), path + ": something odd happened");
  EXPECT_EQ(brdfCompileError(file, "", 30), path + ": the shader does not compile (the driver gives no reason)");
  EXPECT_EQ(brdfCompileError(file, "0:31(1): error: \x1b[31mred\n", 30), path + ":10: \\x1B[31mred");
}

TEST(BrdfFile, DisplayNameIsTheFileNameWithoutFolder)
{
  EXPECT_EQ(brdfDisplayName("data/brdf/ward-anisotropic.brdf"), "ward-anisotropic.brdf");
  EXPECT_EQ(brdfDisplayName("glossy.brdf"), "glossy.brdf");
  EXPECT_EQ(brdfDisplayName("/x/model.txt"), "model.txt");
}
