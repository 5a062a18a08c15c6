// The GPU gets exactly the text of the generated slLightingTables.glsl and of
// slLighting.glsl (and of slNormalMapping.glsl and slFalseColor.glsl), the
// files the C++ compilations include, and that text is valid
// GLSL 1.50 (checked with glslangValidator, which scripts/install-deps.sh
// installs: its absence is a failure, not a skip).
#include "shadelab/LightingShaderSource.h"

#include "TestFolder.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <unistd.h>

TEST(ShaderSource, EmbedsTheGLSLFileVerbatim)
{
  std::ifstream in(SHADELAB_LIGHTING_GLSL);
  std::stringstream file;
  file << in.rdbuf();
  ASSERT_FALSE(file.str().empty());
  std::ifstream tablesIn(SHADELAB_LIGHTING_TABLES_GLSL);
  std::stringstream tables;
  tables << tablesIn.rdbuf();
  ASSERT_FALSE(tables.str().empty());
  EXPECT_EQ(shadelab::lightingTablesShaderSource(), tables.str());
  EXPECT_EQ(shadelab::lightingShaderSource(), "#define SL_FUNC\n" + tables.str() + file.str());
}

TEST(ShaderSource, EmbedsTheNormalMappingAndFalseColourFilesVerbatim)
{
  const std::string folder = std::string(SHADELAB_LIGHTING_GLSL).substr(0, std::string(SHADELAB_LIGHTING_GLSL).rfind('/'));
  for (const auto& [file, source] : { std::make_pair(std::string("/slNormalMapping.glsl"), &shadelab::normalMappingShaderSource),
         std::make_pair(std::string("/slFalseColor.glsl"), &shadelab::falseColorShaderSource) })
  {
    std::ifstream in(folder + file);
    std::stringstream text;
    text << in.rdbuf();
    ASSERT_FALSE(text.str().empty()) << file;
    EXPECT_EQ(source(), text.str()) << file;
  }
}

TEST(ShaderSource, CompilesAsGLSL150)
{
  if (std::system("command -v glslangValidator > /dev/null 2>&1") != 0)
  {
    FAIL() << "glslangValidator not installed (Debian package glslang-tools; run scripts/install-deps.sh)";
  }
  const TestFolder folder;
  ASSERT_TRUE(folder.valid());
  const std::string path = folder.path("lighting.frag");
  {
    std::ofstream out(path);
    out << "#version 150\n"
        << shadelab::lightingShaderSource() << shadelab::normalMappingShaderSource()
        << shadelab::falseColorShaderSource()
        << "uniform slLight lights[8];\nuniform slMaterial material;\nuniform int model;\n"
           "in vec3 P;\nin vec3 N;\nout vec4 color;\n"
           "void main()\n{\n  slTerms t = slZeroTerms();\n"
           "  for (int i = 0; i < 8; ++i)\n  {\n"
           "    t = slAddTerms(t, slShadeLight(lights[i], material, model, P, N, vec3(1.0f, 0.0f, 0.0f), vec3(0.0f)));\n  }\n"
           "  vec3 n = slTangentToSurface(slDecodeNormal(N, -1.0f, 2.0f), N, P, 1.0f);\n"
           "  color = vec4(slTotal(slAddEmission(t, material)) + slRamp(n.x) + slDiverging(n.y), 1.0f);\n}\n";
  }
  const std::string command = "glslangValidator " + path + " > " + path + ".log 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream log(path + ".log");
  std::stringstream text;
  text << log.rdbuf();
  EXPECT_EQ(status, 0) << text.str();
}
