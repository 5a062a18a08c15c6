// The legacy VTK check's cursor (sllegacyvtk::Walker, slLegacyVTKWalker.h):
// the words, counts, names and values a keyword announces, and string
// arrays, read as vtkDataReader reads them, ASCII or BINARY. Apart from the
// grammar (slLegacyVTKCheck.cxx) because this is where the bytes are read:
// each read checks that the file holds what VTK will read there.
#include "slLegacyVTKWalker.h"

#include "slMeshAttributeCheck.h"

#include "shadelab/PrintableText.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <limits>

namespace
{
/// Bytes per value of a legacy type name as vtkDataWriter writes and
/// vtkDataReader reads it; 0 for "bit" (packed), -1 unknown. vtkIdType is
/// written and read as 32-bit int; "string" values have a size of their own
/// (Walker::strings()), given here as 1, the least.
int typeSize(std::string type)
{
  std::transform(type.begin(), type.end(), type.begin(), [](unsigned char c) { return std::tolower(c); });
  struct Type
  {
    const char* name;
    int size;
  };
  static const Type types[] = { { "bit", 0 }, { "char", 1 }, { "signed_char", 1 }, { "unsigned_char", 1 },
    { "short", 2 }, { "unsigned_short", 2 }, { "int", 4 }, { "unsigned_int", 4 }, { "long", 8 },
    { "unsigned_long", 8 }, { "vtkidtype", 4 }, { "vtktypeint64", 8 }, { "vtktypeuint64", 8 },
    { "vtktypeint32", 4 }, { "vtktypeuint32", 4 }, { "float", 4 }, { "double", 8 }, { "string", 1 } };
  for (const Type& t : types)
  {
    if (type == t.name)
    {
      return t.size;
    }
  }
  return -1;
}
} // namespace

namespace sllegacyvtk
{
std::string encodedProblem(const std::string& text)
{
  if (text.size() < 3 && text.find('%') != std::string::npos)
  {
    return "\"" + shadelab::printableText(text) +
      "\" holds a % in fewer than 3 characters, which VTK decodes by reading past its end";
  }
  return "";
}

bool Walker::atEnd()
{
  this->skipSpace();
  return this->Position >= this->Bytes.size();
}

std::string Walker::word(const char* what)
{
  this->skipSpace();
  const size_t begin = this->Position;
  while (this->Position < this->Bytes.size() && !std::isspace(static_cast<unsigned char>(this->Bytes[this->Position])))
  {
    ++this->Position;
  }
  if (begin == this->Position)
  {
    fail("line " + std::to_string(this->line()) + ": the file ends where " + what + " should be");
  }
  // VTK reads words into 256-byte buffers: a longer one would be split.
  if (this->Position - begin > 255)
  {
    fail("line " + std::to_string(this->line()) + ": a word longer than 255 characters");
  }
  return this->Bytes.substr(begin, this->Position - begin);
}

long long Walker::count(const char* what)
{
  const std::string text = this->word(what);
  errno = 0;
  char* end = nullptr;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  if (end == text.c_str() || *end != '\0' || errno == ERANGE || value < 0 || value > (1LL << 40))
  {
    fail("line " + std::to_string(this->line()) + ": " + what + " \"" + shadelab::printableText(text) +
      "\" is not a count");
  }
  return value;
}

std::string Walker::name(const char* what, const std::string& section)
{
  const std::string text = this->word(what);
  this->checkName(text, section);
  return text;
}

void Walker::checkName(const std::string& text, const std::string& section)
{
  const std::string problem = encodedProblem(text);
  if (!problem.empty())
  {
    fail("line " + std::to_string(this->line()) + ": " + section + ": name " + problem);
  }
}

void Walker::values(long long tuples, long long components, const std::string& type, const std::string& section,
  std::vector<long long>* keep)
{
  const int size = typeSize(type);
  if (size < 0)
  {
    fail("line " + std::to_string(this->line()) + ": " + section + ": unknown data type \"" +
      shadelab::printableText(type) + "\"");
  }
  // VTK sizes an array by components times tuples (a product that can
  // wrap) and allocates per-tuple buffers of the component count even when
  // there are no tuples: neither may exceed what the file can hold.
  if (components < 1 || static_cast<unsigned long long>(components) > this->Bytes.size())
  {
    fail("line " + std::to_string(this->line()) + ": " + section + ": " + std::to_string(components) +
      " components, " +
      (components < 1 ? "fewer than 1"
                      : "more than the file's " + std::to_string(this->Bytes.size()) + " bytes could hold"));
  }
  if (tuples > std::numeric_limits<long long>::max() / components ||
    static_cast<unsigned long long>(tuples * components) / 8 > this->Bytes.size())
  {
    fail("line " + std::to_string(this->line()) + ": " + section + ": " + std::to_string(tuples) + " tuples of " +
      std::to_string(components) + " components, more values than the file's " + std::to_string(this->Bytes.size()) +
      " bytes could hold");
  }
  const long long n = tuples * components;
  this->Components = components;
  if (upper(type) == "STRING")
  {
    this->strings(n, section);
    return;
  }
  if (!this->Binary)
  {
    const bool asFloat = upper(type) == "FLOAT";
    for (long long i = 0; i < n; ++i)
    {
      const std::string text =
        this->word(("value " + std::to_string(i + 1) + " of " + std::to_string(n) + " of " + section).c_str());
      char* end = nullptr;
      std::strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0')
      {
        fail("line " + std::to_string(this->line()) + ": " + section + ": \"" + shadelab::printableText(text) +
          "\" is not a number");
      }
      // VTK reads each value with >>, which reads no "nan" or "inf" and
      // fails on a float beyond float range: it would stop there and take
      // the value for the next keyword ("Unrecognized keyword: nan").
      const std::string finite = slNonFiniteTextProblem(text, asFloat);
      if (!finite.empty())
      {
        fail("line " + std::to_string(this->line()) + ": " + section + ": " + finite);
      }
      if (keep)
      {
        // VTK reads a legacy cell list with operator>> into int: "1e23"
        // or "3.0" stops it there, as does a value beyond int.
        errno = 0;
        char* intEnd = nullptr;
        const long long id = std::strtoll(text.c_str(), &intEnd, 10);
        if (*intEnd != '\0' || errno == ERANGE || id < std::numeric_limits<int>::min() ||
          id > std::numeric_limits<int>::max())
        {
          fail("line " + std::to_string(this->line()) + ": " + section + ": \"" + shadelab::printableText(text) +
            "\" is not an integer VTK reads as int");
        }
        keep->push_back(id);
      }
    }
    return;
  }
  // Binary: the values start on the line after the keyword, big-endian.
  const size_t newline = this->Bytes.find('\n', this->Position);
  // VTK skips the rest of the keyword line with getline(line, 256): a
  // longer rest fails the stream, and the read of the values does nothing.
  if (n > 0 && std::min(newline, this->Bytes.size()) - this->Position > 255)
  {
    fail("line " + std::to_string(this->line()) + ": " + section +
      ": keyword line longer than the 255 bytes VTK reads before binary data");
  }
  const size_t start = newline == std::string::npos ? this->Bytes.size() : newline + 1;
  const unsigned long long bytes =
    size == 0 ? (static_cast<unsigned long long>(n) + 7) / 8 : static_cast<unsigned long long>(n) * size;
  if (bytes > this->Bytes.size() - std::min(start, this->Bytes.size()))
  {
    fail(section + ": " + std::to_string(n) + " values need " + std::to_string(bytes) + " bytes, the file has " +
      std::to_string(this->Bytes.size() - std::min(start, this->Bytes.size())) + " after its keyword line");
  }
  if (keep)
  {
    for (long long i = 0; i < n; ++i)
    {
      unsigned long long v = 0;
      for (int b = 0; b < size; ++b)
      {
        v = v << 8 | static_cast<unsigned char>(this->Bytes[start + static_cast<size_t>(i * size + b)]);
      }
      keep->push_back(size == 4 ? static_cast<long long>(static_cast<std::int32_t>(v)) : static_cast<long long>(v));
    }
  }
  this->Position = start + static_cast<size_t>(bytes);
}

void Walker::strings(long long n, const std::string& section)
{
  const size_t newline = this->Bytes.find('\n', this->Position);
  // VTK skips the rest of a binary keyword line with getline(line, 256)
  // even when there are no strings.
  if (this->Binary && std::min(newline, this->Bytes.size()) - this->Position > 255)
  {
    fail("line " + std::to_string(this->line()) + ": " + section +
      ": keyword line longer than the 255 bytes VTK reads before binary data");
  }
  this->Position = newline == std::string::npos ? this->Bytes.size() : newline + 1;
  const size_t size = this->Bytes.size();
  for (long long i = 0; i < n; ++i)
  {
    if (this->Position >= size)
    {
      fail("line " + std::to_string(this->line()) + ": " + section + ": the file ends after " + std::to_string(i) +
        " of " + std::to_string(n) + " strings");
    }
    if (!this->Binary)
    {
      const long at = this->line();
      const size_t end = std::min(this->Bytes.find('\n', this->Position), size);
      const std::string problem = encodedProblem(this->Bytes.substr(this->Position, end - this->Position));
      if (!problem.empty())
      {
        fail("line " + std::to_string(at) + ": " + section + ": string " + problem);
      }
      this->Position = end == size ? size : end + 1;
      continue;
    }
    const unsigned char first = static_cast<unsigned char>(this->Bytes[this->Position]);
    const int header = (first >> 6) == 3 ? 1 : (first >> 6) == 2 ? 2 : (first >> 6) == 1 ? 4 : 8;
    if (size - this->Position < static_cast<size_t>(header))
    {
      fail(section + ": string " + std::to_string(i + 1) + " of " + std::to_string(n) +
        ": the file ends within its length");
    }
    unsigned long long length = 0;
    for (int b = 0; b < header; ++b)
    {
      length = length << 8 | static_cast<unsigned char>(this->Bytes[this->Position + static_cast<size_t>(b)]);
    }
    if (header < 8)
    {
      length &= (1ULL << (8 * header - 2)) - 1;
    }
    this->Position += static_cast<size_t>(header);
    if (length > size - this->Position)
    {
      fail(section + ": string " + std::to_string(i + 1) + " of " + std::to_string(n) + " is " +
        std::to_string(length) + " bytes long, the file has " + std::to_string(size - this->Position) +
        " after its length");
    }
    this->Position += static_cast<size_t>(length);
  }
}

long Walker::line() const
{
  if (this->Position < this->CountedTo)
  {
    this->CountedTo = 0;
    this->LinesBefore = 0;
  }
  this->LinesBefore += std::count(this->Bytes.begin() + static_cast<std::ptrdiff_t>(this->CountedTo),
    this->Bytes.begin() + static_cast<std::ptrdiff_t>(this->Position), '\n');
  this->CountedTo = this->Position;
  return 1 + static_cast<long>(this->LinesBefore);
}

void Walker::skipSpace()
{
  while (this->Position < this->Bytes.size() && std::isspace(static_cast<unsigned char>(this->Bytes[this->Position])))
  {
    ++this->Position;
  }
}
} // namespace sllegacyvtk
