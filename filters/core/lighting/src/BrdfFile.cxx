#include "shadelab/BrdfFile.h"

#include "shadelab/Error.h"
#include "shadelab/InputFile.h"
#include "shadelab/PrintableText.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace shadelab
{
namespace
{

/// Longest file read: the files are a few kilobytes of text; a larger one is
/// not a .brdf file.
constexpr std::streamoff kMaxFileBytes = 1 << 20;

/// How much of a quoted value or a driver's message a line shows.
constexpr size_t kQuotedBytes = 40;
constexpr size_t kMessageBytes = 300;

std::string trim(const std::string& s)
{
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos)
  {
    return "";
  }
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

std::vector<std::string> words(const std::string& s)
{
  std::vector<std::string> out;
  std::istringstream in(s);
  std::string word;
  while (in >> word)
  {
    out.push_back(word);
  }
  return out;
}

std::string quoted(const std::string& s)
{
  return "\"" + printableText(s, kQuotedBytes) + "\"";
}

std::string number(float value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%g", static_cast<double>(value));
  return text;
}

/// Throws "PATH:LINE: reason".
[[noreturn]] void fail(const std::string& path, int line, const std::string& reason)
{
  throw Error(path + ":" + std::to_string(line) + ": " + reason);
}

/// @p text as a finite float (an optional leading '+' is allowed), or false.
bool parseFloat(const std::string& text, float& value)
{
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (first != last && *first == '+')
  {
    ++first;
  }
  // from_chars takes no '+'; "+-1" is not a number.
  if (first == last || (*first == '-' && first != text.data()))
  {
    return false;
  }
  const auto result = std::from_chars(first, last, value);
  return result.ec == std::errc() && result.ptr == last && std::isfinite(value);
}

/// @p text as a bool: 0, 1, true or false.
bool parseBool(const std::string& text, float& value)
{
  if (text == "1" || text == "true")
  {
    value = 1.0f;
    return true;
  }
  if (text == "0" || text == "false")
  {
    value = 0.0f;
    return true;
  }
  return false;
}

/// Words GLSL reserves (GLSL 1.50, which VTK's OpenGL 3.2 shaders use):
/// a parameter of such a name would make a uniform the compiler rejects
/// with a message far from the parameter's line.
bool isGlslKeyword(const std::string& name)
{
  static const std::array<const char*, 75> keywords = { "attribute", "const", "uniform", "varying",
    "layout", "centroid", "flat", "smooth", "noperspective", "break", "continue", "do", "for",
    "while", "switch", "case", "default", "if", "else", "in", "out", "inout", "float", "int",
    "void", "bool", "true", "false", "invariant", "discard", "return", "mat2", "mat3", "mat4",
    "mat2x2", "mat2x3", "mat2x4", "mat3x2", "mat3x3", "mat3x4", "mat4x2", "mat4x3", "mat4x4",
    "vec2", "vec3", "vec4", "ivec2", "ivec3", "ivec4", "bvec2", "bvec3", "bvec4", "uint",
    "uvec2", "uvec3", "uvec4", "lowp", "mediump", "highp", "precision", "sampler1D",
    "sampler2D", "sampler3D", "samplerCube", "struct", "double", "dvec2", "dvec3", "dvec4",
    "half", "fixed", "long", "short", "unsigned", "input" };
  return std::find_if(keywords.begin(), keywords.end(),
           [&](const char* keyword) { return name == keyword; }) != keywords.end();
}

/// Why @p name cannot be a parameter's (uniform's) name, or "".
std::string nameProblem(const std::string& name)
{
  const bool identifier = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) &&
    std::all_of(name.begin(), name.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    });
  if (!identifier)
  {
    return quoted(name) + " is not a GLSL name (letters, digits and _, not starting with a digit)";
  }
  if (name.compare(0, 3, "gl_") == 0 || name.find("__") != std::string::npos)
  {
    return quoted(name) + " is a name GLSL reserves (gl_ prefix or __)";
  }
  if (isGlslKeyword(name))
  {
    return quoted(name) + " is a GLSL keyword";
  }
  return "";
}

const char* kindName(BrdfParameter::Kind kind)
{
  switch (kind)
  {
    case BrdfParameter::Kind::Float:
      return "float";
    case BrdfParameter::Kind::Bool:
      return "bool";
    case BrdfParameter::Kind::Color:
      return "color";
  }
  return "";
}

/// One line of the parameter block (without its comment), as a parameter.
BrdfParameter parseParameter(const std::string& path, int line, const std::vector<std::string>& w)
{
  BrdfParameter p;
  p.line = line;
  const std::string& keyword = w[0];
  size_t expected = 0;
  const char* form = "";
  if (keyword == "float")
  {
    p.kind = BrdfParameter::Kind::Float;
    expected = 5;
    form = "float NAME MIN MAX DEFAULT";
  }
  else if (keyword == "bool")
  {
    p.kind = BrdfParameter::Kind::Bool;
    expected = 3;
    form = "bool NAME DEFAULT";
  }
  else if (keyword == "color")
  {
    p.kind = BrdfParameter::Kind::Color;
    expected = 5;
    form = "color NAME R G B";
  }
  else
  {
    fail(path, line, "unknown parameter type " + quoted(keyword) + " (float, bool or color)");
  }
  if (w.size() != expected)
  {
    fail(path, line,
      keyword + " needs " + std::to_string(expected - 1) + " values (" + form + "), the line has " +
        std::to_string(w.size() - 1));
  }
  p.name = w[1];
  const std::string problem = nameProblem(p.name);
  if (!problem.empty())
  {
    fail(path, line, problem);
  }
  auto value = [&](size_t i, const char* what) {
    float v = 0.0f;
    if (!parseFloat(w[i], v))
    {
      fail(path, line, p.name + ": " + what + " " + quoted(w[i]) + " is not a finite number");
    }
    return v;
  };
  if (p.kind == BrdfParameter::Kind::Float)
  {
    p.minimum = value(2, "minimum");
    p.maximum = value(3, "maximum");
    p.defaultValue.x = value(4, "default");
    if (p.minimum > p.maximum)
    {
      fail(path, line,
        p.name + ": the minimum " + number(p.minimum) + " is above the maximum " + number(p.maximum));
    }
    if (p.defaultValue.x < p.minimum || p.defaultValue.x > p.maximum)
    {
      fail(path, line,
        p.name + ": the default " + number(p.defaultValue.x) + " is out of range [" + number(p.minimum) +
          ", " + number(p.maximum) + "]");
    }
  }
  else if (p.kind == BrdfParameter::Kind::Bool)
  {
    if (!parseBool(w[2], p.defaultValue.x))
    {
      fail(path, line, p.name + ": the default " + quoted(w[2]) + " is not a bool (0, 1, true or false)");
    }
  }
  else
  {
    p.defaultValue = glm::vec3(value(2, "red"), value(3, "green"), value(4, "blue"));
  }
  return p;
}

/// True if @p shader has the identifier BRDF followed by "(".
bool mentionsBrdfFunction(const std::string& shader)
{
  for (size_t at = shader.find("BRDF"); at != std::string::npos; at = shader.find("BRDF", at + 1))
  {
    const bool startsWord = at == 0 ||
      !(std::isalnum(static_cast<unsigned char>(shader[at - 1])) || shader[at - 1] == '_');
    const size_t next = shader.find_first_not_of(" \t\r\n", at + 4);
    if (startsWord && next != std::string::npos && shader[next] == '(')
    {
      return true;
    }
  }
  return false;
}

/// @p shader with its // and /* */ comments replaced by spaces (line
/// breaks kept).
std::string withoutComments(const std::string& shader)
{
  std::string out = shader;
  for (size_t at = 0; at < out.size(); ++at)
  {
    if (out.compare(at, 2, "//") == 0)
    {
      for (; at < out.size() && out[at] != '\n'; ++at)
      {
        out[at] = ' ';
      }
    }
    else if (out.compare(at, 2, "/*") == 0)
    {
      const size_t end = out.find("*/", at + 2);
      const size_t stop = end == std::string::npos ? out.size() : end + 2;
      for (; at < stop; ++at)
      {
        out[at] = out[at] == '\n' ? '\n' : ' ';
      }
      --at;
    }
  }
  return out;
}

bool isNameChar(char c)
{
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

/// The names of the arguments of the definition of BRDF in @p shader
/// ("vec3 BRDF(vec3 L, ...) {"): the last name in each comma-separated part
/// of its argument list. Empty when the shader has no such definition.
std::vector<std::string> brdfArgumentNames(const std::string& shader)
{
  const std::string code = withoutComments(shader);
  for (size_t at = code.find("BRDF"); at != std::string::npos; at = code.find("BRDF", at + 1))
  {
    if ((at > 0 && isNameChar(code[at - 1])) || (at + 4 < code.size() && isNameChar(code[at + 4])))
    {
      continue;
    }
    const size_t open = code.find_first_not_of(" \t\r\n", at + 4);
    if (open == std::string::npos || code[open] != '(')
    {
      continue;
    }
    const size_t close = code.find(')', open);
    const size_t body = close == std::string::npos ? close : code.find_first_not_of(" \t\r\n", close + 1);
    if (body == std::string::npos || code[body] != '{')
    {
      continue; // a call or a declaration
    }
    std::vector<std::string> names;
    std::string last, word;
    for (size_t i = open + 1; i <= close; ++i)
    {
      const char c = code[i];
      if (isNameChar(c))
      {
        word += c;
        continue;
      }
      if (!word.empty())
      {
        last = word;
        word.clear();
      }
      if ((c == ',' || c == ')') && !last.empty())
      {
        names.push_back(last);
        last.clear();
      }
    }
    return names;
  }
  return {};
}

std::string startsWith(const std::string& s, const std::string& prefix)
{
  return s.compare(0, prefix.size(), prefix) == 0 ? s.substr(prefix.size()) : std::string();
}

} // namespace

BrdfFile parseBrdfText(const std::string& text, const std::string& path)
{
  enum class Block
  {
    None,
    Parameters,
    Shader
  };
  BrdfFile file;
  file.path = path;
  if (text.empty())
  {
    throw Error(path + ": the file is empty");
  }
  Block block = Block::None;
  int blockLine = 0;
  bool sawParameters = false, sawShader = false, sawContent = false;
  int lineNumber = 0;
  size_t start = 0;
  while (start < text.size())
  {
    size_t end = text.find('\n', start);
    if (end == std::string::npos)
    {
      end = text.size();
    }
    std::string line = text.substr(start, end - start);
    start = end + 1;
    ++lineNumber;
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    const auto control = std::find_if(line.begin(), line.end(), [](char c) {
      const auto u = static_cast<unsigned char>(c);
      return (u < 0x20 && c != '\t') || u == 0x7F;
    });
    if (control != line.end())
    {
      fail(path, lineNumber, "control byte " + printableText(std::string(1, *control)) + " in the text");
    }
    const std::string trimmed = trim(line);
    if (block == Block::Shader)
    {
      if (trimmed == "::end shader")
      {
        block = Block::None;
        continue;
      }
      if (trimmed.compare(0, 2, "::") == 0)
      {
        fail(path, lineNumber,
          quoted(trimmed) + " inside the shader block (::begin shader on line " + std::to_string(blockLine) +
            " has no ::end shader before it)");
      }
      file.shader += line;
      file.shader += '\n';
      continue;
    }
    // The parameter block and the text around the blocks: '#' starts a comment.
    const std::string content = trim(trimmed.substr(0, trimmed.find('#')));
    if (content.empty())
    {
      continue;
    }
    if (block == Block::Parameters)
    {
      if (content == "::end parameters")
      {
        block = Block::None;
        continue;
      }
      if (content.compare(0, 2, "::") == 0)
      {
        fail(path, lineNumber,
          quoted(content) + " inside the parameter block (::begin parameters on line " +
            std::to_string(blockLine) + " has no ::end parameters before it)");
      }
      BrdfParameter p = parseParameter(path, lineNumber, words(content));
      for (const BrdfParameter& earlier : file.parameters)
      {
        if (earlier.name == p.name)
        {
          fail(path, lineNumber,
            "a second parameter named " + quoted(p.name) + " (the first is on line " +
              std::to_string(earlier.line) + ")");
        }
      }
      file.parameters.push_back(p);
      continue;
    }
    const std::vector<std::string> w = words(content);
    if (content == "analytic")
    {
      if (sawContent)
      {
        fail(path, lineNumber, "\"analytic\" may only be the first line");
      }
      sawContent = true;
      continue;
    }
    sawContent = true;
    if (w.size() == 2 && w[0] == "::begin" && (w[1] == "parameters" || w[1] == "shader"))
    {
      const bool parameters = w[1] == "parameters";
      bool& seen = parameters ? sawParameters : sawShader;
      if (seen)
      {
        fail(path, lineNumber, "a second " + w[1] + " block");
      }
      seen = true;
      block = parameters ? Block::Parameters : Block::Shader;
      blockLine = lineNumber;
      if (!parameters)
      {
        file.shaderFirstLine = lineNumber + 1;
      }
      continue;
    }
    if (!w.empty() && w[0] == "::begin")
    {
      fail(path, lineNumber,
        "unknown block " + quoted(trim(startsWith(content, "::begin"))) + " (parameters or shader)");
    }
    if (!w.empty() && w[0] == "::end")
    {
      fail(path, lineNumber, quoted(content) + " without its ::begin");
    }
    fail(path, lineNumber,
      "unexpected text " + quoted(content) +
        " outside the blocks (the file holds \"analytic\", # comments, a parameters and a shader block)");
  }
  if (block != Block::None)
  {
    const char* name = block == Block::Shader ? "shader" : "parameters";
    fail(path, blockLine,
      std::string("::begin ") + name + " has no ::end " + name + " (the file ends on line " +
        std::to_string(lineNumber) + ")");
  }
  if (!sawShader)
  {
    throw Error(path + ": no shader block (::begin shader ... ::end shader)");
  }
  if (!mentionsBrdfFunction(file.shader))
  {
    fail(path, file.shaderFirstLine - 1,
      "the shader block does not define vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)");
  }
  // GLSL lets an argument hide a uniform of the same name: the function
  // would read the argument where the file means the parameter.
  const std::vector<std::string> arguments = brdfArgumentNames(file.shader);
  for (const BrdfParameter& p : file.parameters)
  {
    if (std::find(arguments.begin(), arguments.end(), p.name) != arguments.end())
    {
      fail(path, p.line,
        "parameter " + quoted(p.name) + " has the name of an argument of BRDF, which hides it there (rename it)");
    }
  }
  return file;
}

BrdfFile readBrdfFile(const std::string& path)
{
  // Before the size is asked: a directory or a device has none to go by.
  const std::string fileProblem = inputFileProblem(path, "a BRDF file");
  if (!fileProblem.empty())
  {
    throw Error(path + ": " + fileProblem);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw Error(path + ": cannot open BRDF file: " + openFailureReason(path));
  }
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0)
  {
    throw Error(path + ": cannot read BRDF file");
  }
  if (size > kMaxFileBytes)
  {
    throw Error(path + ": " + std::to_string(size) + " bytes is too large for a .brdf file (at most " +
      std::to_string(kMaxFileBytes) + ")");
  }
  in.seekg(0);
  std::string text(static_cast<size_t>(size), '\0');
  if (!in.read(&text[0], size))
  {
    throw Error(path + ": cannot read BRDF file");
  }
  return parseBrdfText(text, path);
}

std::string brdfDisplayName(const std::string& path)
{
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::vector<glm::vec3> brdfParameterValues(const BrdfFile& file, const std::vector<std::string>& overrides)
{
  std::vector<glm::vec3> values;
  for (const BrdfParameter& p : file.parameters)
  {
    values.push_back(p.defaultValue);
  }
  for (const std::string& text : overrides)
  {
    const std::string place = file.path + ": --param " + quoted(text) + ": ";
    const size_t equals = text.find('=');
    if (equals == std::string::npos)
    {
      throw Error(place + "not NAME=VALUE");
    }
    const std::string name = text.substr(0, equals);
    const std::string value = text.substr(equals + 1);
    const auto found = std::find_if(file.parameters.begin(), file.parameters.end(),
      [&](const BrdfParameter& p) { return p.name == name; });
    if (found == file.parameters.end())
    {
      std::string names;
      for (const BrdfParameter& p : file.parameters)
      {
        names += (names.empty() ? "" : ", ") + p.name;
      }
      throw Error(place + "the file has no parameter " + quoted(name) + " (" +
        (names.empty() ? std::string("it has none") : "it has " + names) + ")");
    }
    const BrdfParameter& p = *found;
    glm::vec3& v = values[static_cast<size_t>(found - file.parameters.begin())];
    if (p.kind == BrdfParameter::Kind::Bool)
    {
      if (!parseBool(value, v.x))
      {
        throw Error(place + p.name + " is a bool: " + quoted(value) + " is not 0, 1, true or false");
      }
      continue;
    }
    if (p.kind == BrdfParameter::Kind::Color)
    {
      std::vector<std::string> parts;
      std::string part;
      std::istringstream in(value);
      while (std::getline(in, part, ','))
      {
        parts.push_back(trim(part));
      }
      glm::vec3 c(0.0f);
      if (parts.size() != 3 || !parseFloat(parts[0], c.x) || !parseFloat(parts[1], c.y) ||
        !parseFloat(parts[2], c.z) || value.back() == ',')
      {
        throw Error(place + p.name + " is a color: " + quoted(value) + " is not three finite numbers R,G,B");
      }
      v = c;
      continue;
    }
    float f = 0.0f;
    if (!parseFloat(value, f))
    {
      throw Error(place + quoted(value) + " is not a finite number");
    }
    if (f < p.minimum || f > p.maximum)
    {
      throw Error(place + p.name + " " + number(f) + " is out of range [" + number(p.minimum) + ", " +
        number(p.maximum) + "] (line " + std::to_string(p.line) + ")");
    }
    v.x = f;
  }
  return values;
}

std::string brdfUniformDeclarations(const BrdfFile& file)
{
  std::string out;
  for (const BrdfParameter& p : file.parameters)
  {
    const char* type = p.kind == BrdfParameter::Kind::Color ? "vec3" : kindName(p.kind);
    out += std::string("uniform ") + type + " " + p.name + ";\n";
  }
  return out;
}

namespace
{

/// Reads the digits at @p at into @p value and moves past them.
bool readNumber(const std::string& s, size_t& at, int& value)
{
  const auto result = std::from_chars(s.data() + at, s.data() + s.size(), value);
  if (result.ec != std::errc() || result.ptr == s.data() + at)
  {
    return false;
  }
  at = static_cast<size_t>(result.ptr - s.data());
  return true;
}

bool skip(const std::string& s, size_t& at, const std::string& text)
{
  if (s.compare(at, text.size(), text) != 0)
  {
    return false;
  }
  at += text.size();
  return true;
}

/// The source line of one log line and the message after the location, in
/// the forms drivers write: Mesa "0:12(5): error: msg", glslang and AMD
/// "ERROR: 0:12: msg", NVIDIA "0(12) : error C0000: msg". Line 0 if the line
/// has no location.
std::pair<int, std::string> locate(const std::string& logLine)
{
  std::string s = trim(logLine);
  size_t at = 0;
  for (const char* prefix : { "ERROR: ", "error: ", "Error: " })
  {
    if (skip(s, at, prefix))
    {
      break;
    }
  }
  int file = 0, line = 0, column = 0;
  size_t after = at;
  bool found = false;
  if (readNumber(s, after, file))
  {
    size_t mesa = after;
    if (skip(s, mesa, ":") && readNumber(s, mesa, line))
    {
      size_t withColumn = mesa;
      if (skip(s, withColumn, "(") && readNumber(s, withColumn, column) && skip(s, withColumn, ")"))
      {
        mesa = withColumn;
      }
      found = skip(s, mesa, ":");
      after = mesa;
    }
    else
    {
      size_t nvidia = after;
      found = skip(s, nvidia, "(") && readNumber(s, nvidia, line) && skip(s, nvidia, ")");
      if (found)
      {
        skip(s, nvidia, " ");
        found = skip(s, nvidia, ":");
        after = nvidia;
      }
    }
  }
  std::string message = trim(found ? s.substr(after) : s);
  // Drop the word "error" (and NVIDIA's code) that the location carries.
  for (const char* prefix : { "error:", "ERROR:", "error " })
  {
    if (message.compare(0, std::char_traits<char>::length(prefix), prefix) == 0)
    {
      const size_t colon = message.find(':');
      message = trim(colon == std::string::npos ? message : message.substr(colon + 1));
      break;
    }
  }
  return { found ? line : 0, message };
}

} // namespace

std::string brdfCompileError(const BrdfFile& file, const std::string& driverLog, int firstShaderLineInSource)
{
  std::vector<std::string> lines;
  std::istringstream in(driverLog);
  for (std::string line; std::getline(in, line);)
  {
    if (!trim(line).empty())
    {
      lines.push_back(line);
    }
  }
  if (lines.empty())
  {
    return file.path + ": the shader does not compile (the driver gives no reason)";
  }
  // The first line that is an error, else the first line.
  auto isError = [](const std::string& line) {
    std::string lower(line);
    std::transform(lower.begin(), lower.end(), lower.begin(),
      [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
    return lower.find("error") != std::string::npos;
  };
  const auto chosen = std::find_if(lines.begin(), lines.end(), isError);
  const auto [sourceLine, rawMessage] = locate(chosen == lines.end() ? lines.front() : *chosen);
  const std::string message = printableText(rawMessage, kMessageBytes);
  const int shaderLines = static_cast<int>(std::count(file.shader.begin(), file.shader.end(), '\n'));
  const int offset = sourceLine - firstShaderLineInSource;
  if (sourceLine > 0 && offset >= 0 && offset < std::max(shaderLines, 1))
  {
    return file.path + ":" + std::to_string(file.shaderFirstLine + offset) + ": " + message;
  }
  // The uniform declarations, when they come right before the shader text,
  // are the parameters' lines.
  const int parameters = static_cast<int>(file.parameters.size());
  if (sourceLine > 0 && offset < 0 && offset >= -parameters)
  {
    const BrdfParameter& p = file.parameters[static_cast<size_t>(parameters + offset)];
    return file.path + ":" + std::to_string(p.line) + ": " + message + " (the uniform of parameter " +
      quoted(p.name) + ")";
  }
  if (sourceLine > 0)
  {
    const std::string where = offset < 0 ? "before the file's shader text"
                                         : "in the code that calls vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)";
    return file.path + ": " + message + " (line " + std::to_string(sourceLine) + " of the compiled source, " + where + ")";
  }
  return file.path + ": " + message;
}

} // namespace shadelab
