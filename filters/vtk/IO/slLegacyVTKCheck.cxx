// Legacy VTK polydata (.vtk, ASCII or BINARY): every section holds the
// values its keyword line announces, within the file, and each legacy cell
// list adds up to its size. vtkPolyDataReader reads past the end of a short
// section (and crashes there).
#include "slMeshFileCheck.h"

#include "shadelab/PrintableText.h"

#include <vtkInformationDoubleKey.h>
#include <vtkInformationDoubleVectorKey.h>
#include <vtkInformationIdTypeKey.h>
#include <vtkInformationIntegerKey.h>
#include <vtkInformationIntegerVectorKey.h>
#include <vtkInformationKeyLookup.h>
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

/// Whether every token of @p tokens is a number (an integer if @p integers).
bool allNumbers(const std::vector<std::string>& tokens, size_t from, bool integers)
{
  for (size_t i = from; i < tokens.size(); ++i)
  {
    char* end = nullptr;
    errno = 0;
    if (integers)
    {
      std::strtoll(tokens[i].c_str(), &end, 10);
    }
    else
    {
      std::strtod(tokens[i].c_str(), &end);
    }
    if (end == tokens[i].c_str() || *end != '\0' || errno == ERANGE)
    {
      return false;
    }
  }
  return true;
}

/// The problem with the "DATA ..." line @p line of the information key
/// NAME @p name LOCATION @p location, or "". vtkDataReader reads a numeric
/// key's values with operator>>, and a failed read leaves its stream failing
/// while it waits for the next non-empty line: it then loops for ever. So a
/// numeric key known to this process (vtkInformationKeyLookup, as VTK looks
/// it up) must have its DATA complete on its line: one number, or for a
/// vector key its length and that many numbers.
std::string metadataDataProblem(const std::string& name, const std::string& location, const std::string& line)
{
  vtkInformationKey* key = vtkInformationKeyLookup::Find(name, location);
  const bool vector = vtkInformationDoubleVectorKey::SafeDownCast(key) ||
    vtkInformationIntegerVectorKey::SafeDownCast(key);
  const bool scalar = vtkInformationDoubleKey::SafeDownCast(key) || vtkInformationIntegerKey::SafeDownCast(key) ||
    vtkInformationIdTypeKey::SafeDownCast(key) || vtkInformationUnsignedLongKey::SafeDownCast(key);
  if (!vector && !scalar)
  {
    return "";
  }
  std::vector<std::string> tokens;
  for (size_t at = 0; (at = line.find_first_not_of(" \t\r", at)) != std::string::npos;)
  {
    const size_t end = line.find_first_of(" \t\r", at);
    tokens.push_back(line.substr(at, end == std::string::npos ? std::string::npos : end - at));
    at = end;
  }
  const std::string what = "METADATA key " + shadelab::printableText(location) + "::" + shadelab::printableText(name);
  const bool integers = vtkInformationIntegerVectorKey::SafeDownCast(key) || vtkInformationIntegerKey::SafeDownCast(key) ||
    vtkInformationIdTypeKey::SafeDownCast(key) || vtkInformationUnsignedLongKey::SafeDownCast(key);
  if (scalar)
  {
    return tokens.size() == 2 && allNumbers(tokens, 1, integers) ? "" : what + ": DATA must be one number";
  }
  if (tokens.size() < 2 || !allNumbers({ tokens[1] }, 0, true))
  {
    return what + ": DATA must give its length and its values";
  }
  const long long length = std::strtoll(tokens[1].c_str(), nullptr, 10);
  if (length < 0 || static_cast<unsigned long long>(length) != tokens.size() - 2 || !allNumbers(tokens, 2, integers))
  {
    return what + ": DATA declares " + tokens[1] + " values and its line holds " + std::to_string(tokens.size() - 2) +
      (allNumbers(tokens, 2, integers) ? "" : ", not all numbers");
  }
  return "";
}

/// Bytes per value of a legacy type name; 0 for "bit" (packed), -1 unknown.
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
    { "unsigned_long", 8 }, { "vtkidtype", 8 }, { "vtktypeint64", 8 }, { "vtktypeuint64", 8 },
    { "vtktypeint32", 4 }, { "vtktypeuint32", 4 }, { "float", 4 }, { "double", 8 } };
  for (const Type& t : types)
  {
    if (type == t.name)
    {
      return t.size;
    }
  }
  return -1;
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

  /// Skips @p n values of @p type after a keyword line; integers are
  /// returned through @p keep when given (legacy cell lists).
  void values(long long n, const std::string& type, const std::string& section, std::vector<long long>* keep = nullptr)
  {
    const int size = typeSize(type);
    if (size < 0)
    {
      fail("line " + std::to_string(this->line()) + ": " + section + ": unknown data type \"" +
        shadelab::printableText(type) + "\"");
    }
    if (!this->Binary)
    {
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

  /// Skips a METADATA block: lines up to and including the next blank one.
  /// An "INFORMATION n" line must be followed by n "NAME" and n "DATA" lines
  /// (VTK reads that many, past the block's end), and the DATA of a numeric
  /// key must hold what the key's type reads (metadataDataProblem()).
  void skipMetadata()
  {
    long long information = -1, names = 0, data = 0;
    std::string keyName, keyLocation;
    for (;;)
    {
      const size_t newline = this->Bytes.find('\n', this->Position);
      if (newline == std::string::npos)
      {
        fail("line " + std::to_string(this->line()) + ": the file ends within a METADATA block");
      }
      const size_t next = this->Bytes.find('\n', newline + 1);
      const std::string lineText = this->Bytes.substr(newline + 1, (next == std::string::npos ? this->Bytes.size() : next) - newline - 1);
      this->Position = newline + 1;
      // VTK reads this block as text lines; a NUL ends its C strings early.
      if (lineText.find('\0') != std::string::npos)
      {
        fail("line " + std::to_string(this->line()) + ": a NUL byte within a METADATA block");
      }
      if (lineText.find_first_not_of(" \t\r") == std::string::npos)
      {
        if (information >= 0 && (names != information || data != information))
        {
          fail("line " + std::to_string(this->line()) + ": METADATA announces " + std::to_string(information) +
            " information keys and holds " + std::to_string(std::min(names, data)));
        }
        return;
      }
      if (lineText.rfind("INFORMATION ", 0) == 0)
      {
        information = std::strtoll(lineText.c_str() + 12, nullptr, 10);
      }
      if (lineText.rfind("NAME ", 0) == 0)
      {
        ++names;
        char name[256] = "", location[256] = "";
        if (std::sscanf(lineText.c_str(), "NAME %255s LOCATION %255s", name, location) == 2)
        {
          keyName = name;
          keyLocation = location;
        }
      }
      if (lineText.rfind("DATA ", 0) == 0)
      {
        ++data;
        const std::string problem = metadataDataProblem(keyName, keyLocation, lineText);
        if (!problem.empty())
        {
          fail("line " + std::to_string(this->line()) + ": " + problem);
        }
      }
    }
  }

  long line() const { return 1 + static_cast<long>(std::count(this->Bytes.begin(), this->Bytes.begin() + static_cast<long>(this->Position), '\n')); }

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
};

std::string upper(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

void fieldArrays(Walker& w, const std::string& section)
{
  w.word("the field name");
  const long long arrays = w.count("the number of field arrays");
  for (long long a = 0; a < arrays; ++a)
  {
    const std::string name = w.word("a field array name");
    if (upper(name) == "METADATA")
    {
      w.skipMetadata();
      --a;
      continue;
    }
    const long long components = w.count("the number of components");
    const long long tuples = w.count("the number of tuples");
    const std::string type = w.word("the data type");
    w.values(components * tuples, type, section + " array \"" + shadelab::printableText(name) + "\"");
  }
}

/// The attribute sections after POINT_DATA n or CELL_DATA n.
void attributes(Walker& w, long long n, const std::string& keyword, bool binary)
{
  const std::string section = keyword;
  if (keyword == "SCALARS")
  {
    w.word("the scalars name");
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
    w.values(n * components, type, section);
  }
  else if (keyword == "LOOKUP_TABLE")
  {
    w.word("the lookup table name");
    w.values(4 * w.count("the lookup table size"), binary ? "unsigned_char" : "float", section);
  }
  else if (keyword == "VECTORS" || keyword == "NORMALS")
  {
    w.word("the array name");
    w.values(3 * n, w.word("the data type"), section);
  }
  else if (keyword == "TEXTURE_COORDINATES")
  {
    w.word("the array name");
    const long long dim = w.count("the dimension");
    w.values(dim * n, w.word("the data type"), section);
  }
  else if (keyword == "TENSORS" || keyword == "TENSORS6")
  {
    w.word("the array name");
    w.values((keyword == "TENSORS" ? 9 : 6) * n, w.word("the data type"), section);
  }
  else if (keyword == "COLOR_SCALARS")
  {
    w.word("the array name");
    const long long m = w.count("the number of values");
    w.values(m * n, binary ? "unsigned_char" : "float", section);
  }
  else if (keyword == "GLOBAL_IDS" || keyword == "PEDIGREE_IDS")
  {
    w.word("the array name");
    w.values(n, w.word("the data type"), section);
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
  Walker w(bytes, binary, end);
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
    else if (keyword == "METADATA")
    {
      w.skipMetadata();
    }
    else if (keyword == "POINTS")
    {
      points = w.count("the number of points");
      w.values(3 * points, w.word("the points' data type"), "POINTS");
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
        w.values(n, w.word("the offsets' type"), keyword + " OFFSETS");
        if (upper(w.word("CONNECTIVITY")) != "CONNECTIVITY")
        {
          fail("line " + std::to_string(w.line()) + ": " + keyword + ": expected CONNECTIVITY after the offsets");
        }
        w.values(size, w.word("the connectivity type"), keyword + " CONNECTIVITY");
        cells += n > 0 ? n - 1 : 0;
        continue;
      }
      // Legacy: per cell a point count and the ids, adding up to size.
      std::vector<long long> list;
      w.values(size, "int", keyword, &list);
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
        if (next == "METADATA") // an array's information keys
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
