#ifndef shadelab_BrdfFile_h
#define shadelab_BrdfFile_h
/**
 * @file BrdfFile.h
 * @brief BRDF Explorer's analytic `.brdf` files: a parameter block and a
 * GLSL function `vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)`.
 *
 * The format, as the files of Disney's BRDF Explorer use it:
 *
 *     analytic
 *     # a comment
 *     ::begin parameters
 *     float NAME MIN MAX DEFAULT
 *     bool NAME DEFAULT            (0 or 1; true and false are taken too)
 *     color NAME R G B
 *     ::end parameters
 *     ::begin shader
 *     ... GLSL defining vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) ...
 *     ::end shader
 *
 * The `analytic` line is optional; outside the blocks only blank lines and
 * `#` comments may appear; in the parameter block a `#` starts a comment
 * to the end of the line. Lines may end in CRLF. Each parameter becomes a
 * uniform of its name (float, bool or vec3) that the shader reads. Every
 * other construction is rejected with one line, `FILE:LINE: reason`.
 */

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace shadelab
{

/// One parameter of a .brdf file's "::begin parameters" block.
struct BrdfParameter
{
  enum class Kind
  {
    Float,
    Bool,
    Color
  };
  Kind kind = Kind::Float;
  std::string name;
  float minimum = 0.0f, maximum = 1.0f; ///< Float only
  glm::vec3 defaultValue{ 0.0f };       ///< Float: x; Bool: x is 0 or 1; Color: rgb
  int line = 0;                         ///< 1-based line in the file
};

/// A parsed .brdf file.
struct BrdfFile
{
  std::string path;
  std::vector<BrdfParameter> parameters;
  std::string shader;      ///< the text between "::begin shader" and "::end shader"
  int shaderFirstLine = 0; ///< the file's line number of the shader's first line
};

/// Reads and parses the .brdf file @p path. Throws shadelab::Error
/// ("FILE:LINE: reason", one line) for a file that cannot be read or parsed.
BrdfFile readBrdfFile(const std::string& path);

/// Parses @p text as a .brdf file named @p path (used in messages only).
BrdfFile parseBrdfText(const std::string& text, const std::string& path);

/// The name a BRDF from @p path goes by in legends and table columns: the
/// file's name without its folder ("data/brdf/ward.brdf" -> "ward.brdf"),
/// which the extension keeps apart from the built-in models' names.
std::string brdfDisplayName(const std::string& path);

/// Values of the parameters, in the file's order: defaults, then
/// "name=value" @p overrides (--param) in turn; a bool takes
/// true/false/0/1, a colour "r,g,b". Throws shadelab::Error for an unknown
/// name, a bad value or a float outside [min, max].
std::vector<glm::vec3> brdfParameterValues(const BrdfFile& file, const std::vector<std::string>& overrides);

/// GLSL declarations of the parameters as uniforms (`uniform float NAME;`,
/// `uniform bool NAME;`, `uniform vec3 NAME;`, one a line), to put before
/// the shader text.
std::string brdfUniformDeclarations(const BrdfFile& file);

/// The driver's compile log @p driverLog turned into one line
/// "FILE:LINE: message" with LINE the .brdf file's line:
/// @p firstShaderLineInSource is the line (1-based) of the compiled source
/// on which the file's shader text starts. An error outside the file's
/// text (in the code put around it) is "FILE: message (line N of the
/// compiled source)"; an empty log says the shader does not compile.
std::string brdfCompileError(const BrdfFile& file, const std::string& driverLog, int firstShaderLineInSource);

} // namespace shadelab

#endif
