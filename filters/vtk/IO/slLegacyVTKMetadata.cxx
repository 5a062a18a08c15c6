// The METADATA blocks of a legacy VTK file (sllegacyvtk::Walker's
// skipMetadata(), slLegacyVTKWalker.h): component names and information
// keys, read as vtkDataReader reads them. Apart from the cursor's words and
// values because VTK reads these blocks line by line, with sscanf and
// operator>>, and a value it fails to read there makes it loop for ever
// rather than stop; and because only these need VTK's information keys.
#include "slLegacyVTKWalker.h"

#include "shadelab/PrintableText.h"

#include <vtkInformationDoubleKey.h>
#include <vtkInformationDoubleVectorKey.h>
#include <vtkInformationIdTypeKey.h>
#include <vtkInformationIntegerKey.h>
#include <vtkInformationIntegerVectorKey.h>
#include <vtkInformationKeyLookup.h>
#include <vtkInformationStringKey.h>
#include <vtkInformationStringVectorKey.h>
#include <vtkInformationUnsignedLongKey.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

namespace
{
/// How vtkDataReader reads a METADATA value with operator>>.
enum class Number
{
  Real,  // double
  Int,   // int
  Int64, // vtkIdType, unsigned long
};

/// Whether every token of @p tokens from @p from is a whole number of the
/// kind @p kind that operator>> reads completely. libstdc++ reads no "nan",
/// "inf" or hexadecimal doubles, and fails on an int beyond its range; a
/// failed read is what makes vtkDataReader loop for ever.
bool allNumbers(const std::vector<std::string>& tokens, size_t from, Number kind)
{
  for (size_t i = from; i < tokens.size(); ++i)
  {
    const std::string& t = tokens[i];
    char* end = nullptr;
    errno = 0;
    if (kind == Number::Real)
    {
      if (t.find_first_not_of("0123456789+-.eE") != std::string::npos)
      {
        return false;
      }
      std::strtod(t.c_str(), &end);
    }
    else
    {
      const long long value = std::strtoll(t.c_str(), &end, 10);
      if (kind == Number::Int && (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max()))
      {
        return false;
      }
    }
    if (t.empty() || end == t.c_str() || *end != '\0' || errno == ERANGE)
    {
      return false;
    }
  }
  return true;
}

/// The whitespace-separated words of @p line.
std::vector<std::string> words(const std::string& line)
{
  std::vector<std::string> tokens;
  for (size_t at = 0; (at = line.find_first_not_of(" \t\r\v\f", at)) != std::string::npos;)
  {
    const size_t end = line.find_first_of(" \t\r\v\f", at);
    tokens.push_back(line.substr(at, end == std::string::npos ? std::string::npos : end - at));
    at = end;
  }
  return tokens;
}

/// The problem with the DATA line @p line of the information key @p key
/// (@p what names it), or "". vtkDataReader reads a numeric key's values with
/// operator>>, and a failed read leaves its stream failing while it waits for
/// the next non-empty line: it then loops for ever. So a numeric key must
/// have its DATA complete on its line: one number, or for a vector key its
/// length and that many numbers; a string vector key its count of lines.
std::string metadataDataProblem(vtkInformationKey* key, const std::string& what, const std::string& line)
{
  const bool vector = vtkInformationDoubleVectorKey::SafeDownCast(key) ||
    vtkInformationIntegerVectorKey::SafeDownCast(key);
  const bool strings = vtkInformationStringVectorKey::SafeDownCast(key);
  const std::vector<std::string> tokens = words(line);
  if (tokens.empty() || tokens[0] != "DATA")
  {
    return what + ": expected its DATA line, found \"" + shadelab::printableText(line) + "\"";
  }
  const Number kind = vtkInformationDoubleKey::SafeDownCast(key) || vtkInformationDoubleVectorKey::SafeDownCast(key)
    ? Number::Real
    : vtkInformationIntegerKey::SafeDownCast(key) || vtkInformationIntegerVectorKey::SafeDownCast(key) ? Number::Int
                                                                                                        : Number::Int64;
  if (strings)
  {
    return tokens.size() == 2 && allNumbers(tokens, 1, Number::Int) && tokens[1][0] != '-'
      ? ""
      : what + ": DATA must be its number of lines";
  }
  if (!vector)
  {
    return tokens.size() == 2 && allNumbers(tokens, 1, kind) ? "" : what + ": DATA must be one number";
  }
  if (tokens.size() < 2 || !allNumbers({ tokens[1] }, 0, Number::Int))
  {
    return what + ": DATA must give its length and its values";
  }
  const long long length = std::strtoll(tokens[1].c_str(), nullptr, 10);
  // For length 0 VTK leaves the rest of the line unread, to be taken for the
  // block's next line; a negative one it reserves as a huge size.
  if (length <= 0)
  {
    return what + ": DATA declares " + tokens[1] + " values, VTK reads at least 1";
  }
  if (static_cast<unsigned long long>(length) != tokens.size() - 2 || !allNumbers(tokens, 2, kind))
  {
    return what + ": DATA declares " + tokens[1] + " values and its line holds " + std::to_string(tokens.size() - 2) +
      (allNumbers(tokens, 2, kind) ? "" : ", not all numbers");
  }
  return "";
}
} // namespace

namespace sllegacyvtk
{
void Walker::skipMetadata()
{
  const long long components = this->Components;
  std::string text;
  this->nextLine(text); // the rest of the METADATA line
  for (;;)
  {
    const long at = this->nextLine(text);
    if (text.empty())
    {
      return;
    }
    std::string lower = text;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    if (lower.rfind("component_names", 0) == 0)
    {
      for (long long i = 0; i < components; ++i)
      {
        const long nameAt = this->nextLine(text);
        const std::string problem = encodedProblem(text);
        if (!problem.empty())
        {
          fail("line " + std::to_string(nameAt) + ": METADATA component name " + problem);
        }
      }
    }
    else if (lower.rfind("information", 0) == 0)
    {
      const size_t digits = lower.find_first_not_of(" \t\n\v\f\r", 11);
      if (digits == std::string::npos)
      {
        continue; // no count: VTK warns and goes on
      }
      errno = 0;
      char* end = nullptr;
      const long long keys = std::strtoll(lower.c_str() + digits, &end, 10);
      if (end == lower.c_str() + digits)
      {
        continue; // no number: VTK warns and goes on
      }
      if (errno == ERANGE || keys > std::numeric_limits<int>::max() || keys < std::numeric_limits<int>::min())
      {
        fail("line " + std::to_string(at) + ": METADATA: an information count beyond int");
      }
      this->information(keys, at);
    }
  }
}

void Walker::information(long long keys, long at)
{
  std::string text;
  for (long long k = 0; k < keys; ++k)
  {
    do
    {
      if (this->Position >= this->Bytes.size())
      {
        fail("line " + std::to_string(at) + ": METADATA announces " + std::to_string(keys) +
          " information keys and holds " + std::to_string(k));
      }
      at = this->nextLine(text);
    } while (text.empty());
    char name[256] = "", location[256] = "";
    if (text.rfind("NAME ", 0) != 0 || std::sscanf(text.c_str(), "NAME %255s LOCATION %255s", name, location) != 2)
    {
      continue;
    }
    vtkInformationKey* key = vtkInformationKeyLookup::Find(name, location);
    const std::string what =
      "METADATA key " + shadelab::printableText(location) + "::" + shadelab::printableText(name);
    if (vtkInformationStringKey::SafeDownCast(key))
    {
      at = this->nextLine(text);
      char value[256] = "";
      const std::string problem =
        std::sscanf(text.c_str(), "DATA %255s", value) == 1 ? encodedProblem(value) : std::string();
      if (!problem.empty())
      {
        fail("line " + std::to_string(at) + ": " + what + ": " + problem);
      }
      continue;
    }
    if (!vtkInformationDoubleKey::SafeDownCast(key) && !vtkInformationDoubleVectorKey::SafeDownCast(key) &&
      !vtkInformationIntegerKey::SafeDownCast(key) && !vtkInformationIntegerVectorKey::SafeDownCast(key) &&
      !vtkInformationIdTypeKey::SafeDownCast(key) && !vtkInformationUnsignedLongKey::SafeDownCast(key) &&
      !vtkInformationStringVectorKey::SafeDownCast(key))
    {
      continue; // unknown, or a type VTK does not read: it reads on from the next line
    }
    at = this->nextLine(text);
    const std::string problem = metadataDataProblem(key, what, text);
    if (!problem.empty())
    {
      fail("line " + std::to_string(at) + ": " + problem);
    }
    if (vtkInformationStringVectorKey::SafeDownCast(key))
    {
      const long long lines = std::strtoll(words(text)[1].c_str(), nullptr, 10);
      for (long long i = 0; i < lines; ++i)
      {
        at = this->nextLine(text);
        const std::string valueProblem = encodedProblem(text);
        if (!valueProblem.empty())
        {
          fail("line " + std::to_string(at) + ": " + what + ": " + valueProblem);
        }
      }
    }
  }
}

long Walker::nextLine(std::string& text)
{
  const long at = this->line();
  if (this->Position >= this->Bytes.size())
  {
    fail("line " + std::to_string(at) + ": the file ends within a METADATA block");
  }
  const size_t newline = this->Bytes.find('\n', this->Position);
  const size_t end = newline == std::string::npos ? this->Bytes.size() : newline;
  text = this->Bytes.substr(this->Position, end - this->Position);
  this->Position = newline == std::string::npos ? end : newline + 1;
  // VTK reads this block as text lines into 256-byte buffers, cutting a
  // longer line; a NUL ends its C strings early.
  if (text.find('\0') != std::string::npos)
  {
    fail("line " + std::to_string(at) + ": a NUL byte within a METADATA block");
  }
  if (text.size() > 255)
  {
    fail("line " + std::to_string(at) + ": a METADATA line longer than 255 bytes");
  }
  if (!text.empty() && text.back() == '\r')
  {
    text.pop_back();
  }
  return at;
}
} // namespace sllegacyvtk
