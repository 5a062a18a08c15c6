// Legacy VTK polydata (.vtk, ASCII or BINARY), read as vtkDataReader reads
// it: every section holds the values its keyword line announces, within the
// file, each legacy cell list adds up to its size, and METADATA blocks hold
// what VTK reads without looping for ever. vtkPolyDataReader reads past the
// end of a short section (and crashes there).
#include "slMeshAttributeCheck.h"
#include "slMeshFileCheck.h"

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
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

namespace
{
struct Problem
{
  std::string text;
};

[[noreturn]] void fail(const std::string& text)
{
  throw Problem{ text };
}

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

/// The problem with @p text as vtkDataReader::DecodeString decodes it, or "".
/// It decodes "%XX" escapes, and for a '%' in a string shorter than 3
/// characters its bound (length - 3, unsigned) wraps: it reads past the end.
std::string encodedProblem(const std::string& text)
{
  if (text.size() < 3 && text.find('%') != std::string::npos)
  {
    return "\"" + shadelab::printableText(text) +
      "\" holds a % in fewer than 3 characters, which VTK decodes by reading past its end";
  }
  return "";
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

/// Whether VTK takes @p word for the start of a METADATA block: it peeks 8
/// characters and compares them case-insensitively.
bool isMetadata(const std::string& word)
{
  if (word.size() < 8)
  {
    return false;
  }
  std::string head = word.substr(0, 8);
  std::transform(head.begin(), head.end(), head.begin(), [](unsigned char c) { return std::tolower(c); });
  return head == "metadata";
}

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

std::string upper(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

class Walker
{
public:
  Walker(const std::string& bytes, bool binary, size_t start)
    : Bytes(bytes)
    , Binary(binary)
    , Position(start)
  {
  }

  bool atEnd()
  {
    this->skipSpace();
    return this->Position >= this->Bytes.size();
  }

  /// The next whitespace-separated word.
  std::string word(const char* what)
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

  /// A count: a whole number in [0, 2^40].
  long long count(const char* what)
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

  /// A name as VTK reads it with ReadString and decodes with DecodeString.
  std::string name(const char* what, const std::string& section)
  {
    const std::string text = this->word(what);
    this->checkName(text, section);
    return text;
  }

  /// Fails, at the current line, if VTK cannot decode the name @p text of
  /// @p section (encodedProblem()).
  void checkName(const std::string& text, const std::string& section)
  {
    const std::string problem = encodedProblem(text);
    if (!problem.empty())
    {
      fail("line " + std::to_string(this->line()) + ": " + section + ": name " + problem);
    }
  }

  /// Skips @p tuples tuples of @p components values of @p type after a
  /// keyword line; integers are returned through @p keep when given (legacy
  /// cell lists).
  void values(long long tuples, long long components, const std::string& type, const std::string& section,
    std::vector<long long>* keep = nullptr)
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
        " components, " + (components < 1 ? "fewer than 1" : "more than the file's " + std::to_string(this->Bytes.size()) + " bytes could hold"));
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
        const std::string text = this->word(("value " + std::to_string(i + 1) + " of " + std::to_string(n) + " of " + section).c_str());
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

  /// Skips the @p n values of a string array, as vtkDataReader::ReadArray
  /// reads them after the keyword line. ASCII: one line per value, decoded
  /// with DecodeString. Binary: per value a big-endian length, whose first
  /// byte's top two bits give its size (3: 1 byte, 2: 2, 1: 4, less those
  /// two bits; 0: 8 bytes), then that many bytes; VTK allocates the length
  /// before it reads, so it must lie within the file.
  void strings(long long n, const std::string& section)
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

  /// Skips a METADATA block as vtkDataReader::ReadArray reads it: the
  /// METADATA line, then lines up to an empty one (after a trailing CR; a
  /// line of spaces is not empty to VTK). It compares each line's start
  /// case-insensitively: COMPONENT_NAMES is followed by one name line per
  /// component of the array before, "information" by a count as sscanf's
  /// "%d" reads it (any white space), then information keys
  /// (information()); other lines it ignores.
  void skipMetadata()
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

  /// The @p keys information keys after an "information" line (line @p at),
  /// as vtkDataReader::ReadInformation reads them: each key skips empty
  /// lines, then takes one line; a line starting "NAME " (case-sensitive)
  /// names a key, others are ignored. A key known to this process
  /// (vtkInformationKeyLookup, as VTK looks it up) of a type VTK reads takes
  /// its DATA next (metadataDataProblem()); a string key the next line,
  /// whose word after DATA VTK decodes; a string vector key as many lines
  /// as its DATA gives, each decoded.
  void information(long long keys, long at)
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

  /// The next line of a METADATA block into @p text, as vtkDataReader's
  /// ReadLine reads it (a trailing CR removed); returns its line number.
  long nextLine(std::string& text)
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

  /// The line number at the current position. Counted on from the last
  /// call (the position only moves forward): a METADATA block asks at each
  /// of its lines, and counting from the start each time cost a pass over
  /// the whole file per line.
  long line() const
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

private:
  void skipSpace()
  {
    while (this->Position < this->Bytes.size() && std::isspace(static_cast<unsigned char>(this->Bytes[this->Position])))
    {
      ++this->Position;
    }
  }
  const std::string& Bytes;
  bool Binary;
  size_t Position;
  long long Components = 1; // of the array before, for a METADATA block's COMPONENT_NAMES
  mutable size_t CountedTo = 0;      // line(): where the newlines were counted up to
  mutable std::ptrdiff_t LinesBefore = 0; // and how many there were
};

void fieldArrays(Walker& w, const std::string& section)
{
  w.word("the field name");
  const long long arrays = w.count("the number of field arrays");
  for (long long a = 0; a < arrays; ++a)
  {
    // VTK decodes an array name (DecodeString); the block after an array
    // is its METADATA.
    const std::string name = w.word("a field array name");
    if (isMetadata(name))
    {
      w.skipMetadata();
      --a;
      continue;
    }
    const long long components = w.count("the number of components");
    const long long tuples = w.count("the number of tuples");
    const std::string type = w.word("the data type");
    const std::string array = section + " array \"" + shadelab::printableText(name) + "\"";
    w.checkName(name, array);
    w.values(tuples, components, type, array);
  }
}

/// The attribute sections after POINT_DATA n or CELL_DATA n.
void attributes(Walker& w, long long n, const std::string& keyword, bool binary)
{
  const std::string section = keyword;
  if (keyword == "SCALARS")
  {
    w.name("the scalars name", section);
    const std::string type = w.word("the scalars type");
    // An optional component count, then LOOKUP_TABLE and its name.
    long long components = 1;
    std::string next = w.word("LOOKUP_TABLE or the component count");
    if (upper(next) != "LOOKUP_TABLE")
    {
      char* end = nullptr;
      components = std::strtoll(next.c_str(), &end, 10);
      if (*end != '\0' || components < 1 || components > 4)
      {
        fail("line " + std::to_string(w.line()) + ": SCALARS: \"" + shadelab::printableText(next) +
          "\" is not a component count (1 to 4)");
      }
      next = w.word("LOOKUP_TABLE");
    }
    if (upper(next) != "LOOKUP_TABLE")
    {
      fail("line " + std::to_string(w.line()) + ": SCALARS: expected LOOKUP_TABLE");
    }
    w.word("the lookup table name");
    w.values(n, components, type, section);
  }
  else if (keyword == "LOOKUP_TABLE")
  {
    w.word("the lookup table name");
    w.values(w.count("the lookup table size"), 4, binary ? "unsigned_char" : "float", section);
  }
  else if (keyword == "VECTORS" || keyword == "NORMALS")
  {
    w.name("the array name", section);
    w.values(n, 3, w.word("the data type"), section);
  }
  else if (keyword == "TEXTURE_COORDINATES")
  {
    w.name("the array name", section);
    const long long dim = w.count("the dimension");
    w.values(n, dim, w.word("the data type"), section);
  }
  else if (keyword == "TENSORS" || keyword == "TENSORS6")
  {
    w.name("the array name", section);
    w.values(n, keyword == "TENSORS" ? 9 : 6, w.word("the data type"), section);
  }
  else if (keyword == "COLOR_SCALARS")
  {
    w.name("the array name", section);
    const long long m = w.count("the number of values");
    w.values(n, m, binary ? "unsigned_char" : "float", section);
  }
  else if (keyword == "GLOBAL_IDS" || keyword == "PEDIGREE_IDS")
  {
    w.name("the array name", section);
    w.values(n, 1, w.word("the data type"), section);
  }
  else if (keyword == "FIELD")
  {
    fieldArrays(w, section);
  }
  else
  {
    fail("line " + std::to_string(w.line()) + ": unknown keyword \"" + shadelab::printableText(keyword) + "\"");
  }
}

void walk(const std::string& bytes)
{
  // Three header lines: identification, title, ASCII or BINARY.
  size_t end = 0;
  std::string lines[3];
  for (std::string& l : lines)
  {
    const size_t newline = bytes.find('\n', end);
    if (newline == std::string::npos)
    {
      fail("the file ends within its three header lines");
    }
    l = bytes.substr(end, newline - end);
    end = newline + 1;
  }
  // VTK reads each header line into a 256-byte C string, then parses the
  // version from line 1: a NUL byte or a missing version derails it.
  for (int i = 0; i < 3; ++i)
  {
    if (lines[i].size() > 255 || lines[i].find('\0') != std::string::npos)
    {
      fail("line " + std::to_string(i + 1) + ": a header line longer than 255 bytes or holding a NUL byte");
    }
  }
  // The version as VTK reads it: from 5.0 on, cell lists are OFFSETS and
  // CONNECTIVITY; before, one list of counts and ids. Without both numbers
  // VTK assumes 3.0 whatever the file holds.
  int major = 0, minor = 0;
  if (std::sscanf(lines[0].c_str(), "# vtk DataFile Version %d.%d", &major, &minor) != 2)
  {
    fail("line 1: expected \"# vtk DataFile Version N.N\", found \"" + shadelab::printableText(lines[0]) + "\"");
  }
  const std::string kind = upper(lines[2].substr(0, 6));
  const bool binary = kind.rfind("BINARY", 0) == 0;
  if (!binary && kind.rfind("ASCII", 0) != 0)
  {
    fail("line 3: expected ASCII or BINARY, found \"" + shadelab::printableText(lines[2]) + "\"");
  }
  if (!binary && bytes.find('\0') != std::string::npos)
  {
    fail("an ASCII file holding a NUL byte (at byte " + std::to_string(bytes.find('\0')) + ")");
  }
  // VTK reads the file type as one word (ReadString), and the rest of
  // line 3 is the start of the file's content.
  const size_t typeEnd = lines[2].find_first_of(" \t\r\v\f");
  Walker w(bytes, binary, typeEnd == std::string::npos ? end : end - lines[2].size() - 1 + typeEnd);
  const bool offsetCells = major >= 5;
  long long points = -1;
  long long cells = 0;
  while (!w.atEnd())
  {
    const std::string keyword = upper(w.word("a keyword"));
    if (keyword == "DATASET")
    {
      // vtkPolyDataReader compares the first 8 characters only.
      const std::string type = upper(w.word("the dataset type"));
      if (type.compare(0, 8, "POLYDATA") != 0)
      {
        return; // not polydata: vtkPolyDataReader reads nothing and says so
      }
      if (type != "POLYDATA")
      {
        fail("line " + std::to_string(w.line()) + ": dataset type \"" + shadelab::printableText(type) +
          "\" is not POLYDATA, though VTK would read it as POLYDATA");
      }
    }
    else if (keyword == "FIELD")
    {
      fieldArrays(w, "FIELD");
    }
    else if (isMetadata(keyword))
    {
      w.skipMetadata();
    }
    else if (keyword == "POINTS")
    {
      points = w.count("the number of points");
      w.values(points, 3, w.word("the points' data type"), "POINTS");
    }
    else if (keyword == "VERTICES" || keyword == "LINES" || keyword == "POLYGONS" || keyword == "TRIANGLE_STRIPS")
    {
      const long long n = w.count("the number of cells");
      const long long size = w.count("the cell list size");
      if (offsetCells)
      {
        // Version 5: OFFSETS type (n values), CONNECTIVITY type (size values).
        if (upper(w.word("OFFSETS")) != "OFFSETS")
        {
          fail("line " + std::to_string(w.line()) + ": " + keyword + ": expected OFFSETS (file version " +
            std::to_string(major) + "." + std::to_string(minor) + ")");
        }
        w.values(n, 1, w.word("the offsets' type"), keyword + " OFFSETS");
        if (upper(w.word("CONNECTIVITY")) != "CONNECTIVITY")
        {
          fail("line " + std::to_string(w.line()) + ": " + keyword + ": expected CONNECTIVITY after the offsets");
        }
        w.values(size, 1, w.word("the connectivity type"), keyword + " CONNECTIVITY");
        cells += n > 0 ? n - 1 : 0;
        continue;
      }
      // Legacy: per cell a point count and the ids, adding up to size.
      std::vector<long long> list;
      w.values(size, 1, "int", keyword, &list);
      size_t at = 0;
      for (long long c = 0; c < n; ++c)
      {
        if (at >= list.size() || list[at] < 0 || static_cast<unsigned long long>(list[at]) > list.size() - at - 1)
        {
          fail(keyword + ": cell " + std::to_string(c) + " of " + std::to_string(n) + " reaches beyond the list of " +
            std::to_string(size) + " values");
        }
        at += static_cast<size_t>(list[at]) + 1;
      }
      if (at != list.size())
      {
        fail(keyword + ": " + std::to_string(n) + " cells use " + std::to_string(at) + " of the list's " +
          std::to_string(size) + " values");
      }
      cells += n;
    }
    else if (keyword == "POINT_DATA" || keyword == "CELL_DATA")
    {
      const long long n = w.count("the number of values");
      if ((keyword == "POINT_DATA" && n != points) || (keyword == "CELL_DATA" && n != cells))
      {
        fail("line " + std::to_string(w.line()) + ": " + keyword + " " + std::to_string(n) + " does not match the " +
          (keyword == "POINT_DATA" ? std::to_string(points) + " points" : std::to_string(cells) + " cells"));
      }
      while (!w.atEnd())
      {
        Walker probe = w;
        const std::string next = upper(probe.word("a keyword"));
        if (next == "POINT_DATA" || next == "CELL_DATA")
        {
          break;
        }
        w.word("a keyword");
        if (isMetadata(next)) // an array's information keys
        {
          w.skipMetadata();
          continue;
        }
        attributes(w, n, next, binary);
      }
    }
    else
    {
      fail("line " + std::to_string(w.line()) + ": unknown keyword \"" + shadelab::printableText(keyword) + "\"");
    }
  }
}
} // namespace

std::string slLegacyVTKProblem(const std::string& fileName)
{
  const std::string bytes = slReadWholeFile(fileName);
  try
  {
    walk(bytes);
  }
  catch (const Problem& p)
  {
    return p.text;
  }
  return std::string();
}
