// PLY: a header VTK's PLY library can hold, and a body that holds every row
// the header announces, with list counts that fit their line (ASCII) or the
// file (binary) and face indices that name existing vertices. VTK's PLY code
// calls exit() at an early end of file and reads past a line's values.
#include "slByteOrder.h"
#include "slMeshAttributeCheck.h"
#include "slMeshFileCheck.h"

#include "shadelab/PrintableText.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace
{
/// VTK's PLY code reads each line, header or ASCII row, into a 4096-byte
/// buffer; a longer one fails the stream.
constexpr size_t kLongestLine = 4000;

enum class Format
{
  Ascii,
  Little,
  Big
};

struct Property
{
  std::string name;
  int size = 0;          // bytes of the value (list: of each item)
  int countSize = 0;     // lists: bytes of the count; 0 for scalars
  bool isFloat = false;  // value type
  bool isSigned = false; // value type
  bool countSigned = false;
};

struct Element
{
  std::string name;
  unsigned long long count = 0;
  std::vector<Property> properties;
  long line = 0; ///< of the header line that declares it
};

/// Size in bytes of a PLY scalar type, 0 if unknown; sets the flags.
int typeSize(const std::string& type, bool& isFloat, bool& isSigned)
{
  struct Type
  {
    const char* name;
    int size;
    bool isFloat, isSigned;
  };
  static const Type types[] = { { "char", 1, false, true }, { "int8", 1, false, true }, { "uchar", 1, false, false },
    { "uint8", 1, false, false }, { "short", 2, false, true }, { "int16", 2, false, true },
    { "ushort", 2, false, false }, { "uint16", 2, false, false }, { "int", 4, false, true },
    { "int32", 4, false, true }, { "uint", 4, false, false }, { "uint32", 4, false, false },
    { "float", 4, true, true }, { "float32", 4, true, true }, { "double", 8, true, true },
    { "float64", 8, true, true } };
  for (const Type& t : types)
  {
    if (type == t.name)
    {
      isFloat = t.isFloat;
      isSigned = t.isSigned;
      return t.size;
    }
  }
  return 0;
}

bool isFaceIndexList(const Element& e, const Property& p)
{
  return e.name == "face" && p.countSize > 0 && (p.name == "vertex_indices" || p.name == "vertex_index");
}


/// Whether vtkPLYReader reads @p p of @p e into the normals or texture
/// coordinates, as floats: a NaN or infinity there would reach the filters.
/// (It reads no other float property but x, y, z, which slMeshReader checks
/// as points.)
bool isFloatAttribute(const Element& e, const Property& p)
{
  if (e.name == "face")
  {
    return p.countSize > 0 && p.name == "texcoord";
  }
  static const char* const names[] = { "nx", "ny", "nz", "u", "v", "texture_u", "texture_v" };
  return e.name == "vertex" && p.countSize == 0 &&
    std::find(std::begin(names), std::end(names), p.name) != std::end(names);
}

std::string indexRange(long long index, unsigned long long vertices)
{
  return "vertex index " + std::to_string(index) + " is out of range [0, " + std::to_string(vertices) + ")";
}

std::string rowName(const Element& e, unsigned long long row)
{
  return "element \"" + shadelab::printableText(e.name) + "\" row " + std::to_string(row + 1) + " of " +
    std::to_string(e.count);
}

/// The most corners vtkPLYReader reads in a face: it keeps the count in a
/// byte, and a face of 300 corners came back with 44.
constexpr long long kMaxFaceCorners = 255;

/// "" or what is wrong with a face of @p count corners (list @p p of @p e).
std::string faceSizeProblem(const Element& e, const Property& p, long long count)
{
  if (!isFaceIndexList(e, p) || count <= kMaxFaceCorners)
  {
    return std::string();
  }
  return std::to_string(count) + " corners; VTK's PLY reader takes at most " + std::to_string(kMaxFaceCorners);
}

/// Buffered reading of the binary body, so that values are checked as they
/// come without holding the file.
class Bytes
{
public:
  Bytes(std::istream& in, bool swap)
    : In(in)
    , Swap(swap)
  {
  }
  /// Reads @p n bytes (n <= 8) into @p out, in host order; false at the end.
  bool read(int n, unsigned char* out)
  {
    for (int i = 0; i < n; ++i)
    {
      if (this->Position == this->Buffer.size() && !this->fill())
      {
        return false;
      }
      out[this->Swap ? n - 1 - i : i] = this->Buffer[this->Position++];
    }
    return true;
  }
  /// Skips @p n bytes; false if the file ends first.
  bool skip(unsigned long long n)
  {
    while (n > 0)
    {
      if (this->Position == this->Buffer.size() && !this->fill())
      {
        return false;
      }
      const unsigned long long here = std::min<unsigned long long>(n, this->Buffer.size() - this->Position);
      this->Position += static_cast<size_t>(here);
      n -= here;
    }
    return true;
  }

private:
  bool fill()
  {
    this->Buffer.resize(1 << 16);
    this->In.read(reinterpret_cast<char*>(this->Buffer.data()), static_cast<std::streamsize>(this->Buffer.size()));
    this->Buffer.resize(static_cast<size_t>(this->In.gcount()));
    this->Position = 0;
    return !this->Buffer.empty();
  }
  std::istream& In;
  bool Swap;
  std::vector<unsigned char> Buffer;
  size_t Position = 0;
};

/// An integer value of @p size bytes read in host order.
long long integer(const unsigned char* bytes, int size, bool isSigned)
{
  switch (size)
  {
    case 1:
      return isSigned ? static_cast<long long>(static_cast<std::int8_t>(bytes[0])) : bytes[0];
    case 2:
    {
      std::uint16_t v;
      std::memcpy(&v, bytes, 2);
      return isSigned ? static_cast<long long>(static_cast<std::int16_t>(v)) : v;
    }
    default:
    {
      std::uint32_t v;
      std::memcpy(&v, bytes, 4);
      return isSigned ? static_cast<long long>(static_cast<std::int32_t>(v)) : v;
    }
  }
}

std::string binaryBody(std::istream& in, bool swap, const std::vector<Element>& elements, unsigned long long vertices)
{
  Bytes bytes(in, swap);
  unsigned char value[8];
  for (const Element& e : elements)
  {
    bool fixed = true;
    unsigned long long rowSize = 0;
    for (const Property& p : e.properties)
    {
      fixed = fixed && p.countSize == 0;
      rowSize += static_cast<unsigned long long>(p.size);
    }
    if (fixed)
    {
      // Rows of scalars: skipped in one go (the count is bounded by the
      // file, as skip() stops at its end).
      for (unsigned long long row = 0; row < e.count; row += 1 << 20)
      {
        const unsigned long long rows = std::min<unsigned long long>(e.count - row, 1 << 20);
        if (!bytes.skip(rows * rowSize))
        {
          return "the file ends within " + rowName(e, row) + " or later";
        }
      }
      continue;
    }
    for (unsigned long long row = 0; row < e.count; ++row)
    {
      for (const Property& p : e.properties)
      {
        if (p.countSize == 0)
        {
          if (!bytes.skip(static_cast<unsigned long long>(p.size)))
          {
            return "the file ends within " + rowName(e, row);
          }
          continue;
        }
        if (!bytes.read(p.countSize, value))
        {
          return "the file ends within " + rowName(e, row);
        }
        const long long count = integer(value, p.countSize, p.countSigned);
        if (count < 0)
        {
          return rowName(e, row) + ": list \"" + shadelab::printableText(p.name) + "\" has a negative count";
        }
        const std::string tooLarge = faceSizeProblem(e, p, count);
        if (!tooLarge.empty())
        {
          return rowName(e, row) + ": " + tooLarge;
        }
        if (!isFaceIndexList(e, p) || p.isFloat)
        {
          if (!bytes.skip(static_cast<unsigned long long>(count) * static_cast<unsigned long long>(p.size)))
          {
            return "the file ends within " + rowName(e, row);
          }
          continue;
        }
        for (long long k = 0; k < count; ++k)
        {
          if (!bytes.read(p.size, value))
          {
            return "the file ends within " + rowName(e, row);
          }
          const long long index = integer(value, p.size, p.isSigned);
          if (index < 0 || static_cast<unsigned long long>(index) >= vertices)
          {
            return rowName(e, row) + ": " + indexRange(index, vertices);
          }
        }
      }
    }
  }
  return std::string();
}

/// A whole token as a number (integer if @p integral).
bool parseToken(const std::string& token, bool integral, long long& integer)
{
  errno = 0;
  char* end = nullptr;
  if (integral)
  {
    integer = std::strtoll(token.c_str(), &end, 10);
  }
  else
  {
    std::strtod(token.c_str(), &end);
  }
  return end != token.c_str() && *end == '\0' && errno != ERANGE;
}

/// The words of a row as VTK's PLY code splits it: at spaces, tabs and
/// carriage returns only. A vertical tab or form feed is part of a word there
/// (a stream would split at it and count a word VTK's reader never finds).
class RowWords
{
public:
  explicit RowWords(const std::string& line)
    : Line(line)
  {
  }
  /// The next word into @p word; false after the last.
  bool next(std::string& word)
  {
    auto separator = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    while (this->At < this->Line.size() && separator(this->Line[this->At]))
    {
      ++this->At;
    }
    const size_t start = this->At;
    while (this->At < this->Line.size() && !separator(this->Line[this->At]))
    {
      ++this->At;
    }
    word.assign(this->Line, start, this->At - start);
    return this->At > start;
  }

private:
  const std::string& Line;
  size_t At = 0;
};

std::string asciiBody(std::istream& in, long lineNumber, const std::vector<Element>& elements, unsigned long long vertices)
{
  std::string line, token;
  for (const Element& e : elements)
  {
    for (unsigned long long row = 0; row < e.count; ++row)
    {
      // One row per line, as VTK's PLY code reads them.
      if (!std::getline(in, line))
      {
        return "line " + std::to_string(lineNumber + 1) + ": the file ends before " + rowName(e, row);
      }
      ++lineNumber;
      RowWords words(line);
      const std::string where = "line " + std::to_string(lineNumber) + " (" + rowName(e, row) + "): ";
      // VTK's PLY code finds no words in a line that ends the file without
      // a newline, or that overflows its buffer, and reads on as if the row
      // were there.
      if (in.eof())
      {
        return where + "no newline at the end of the row";
      }
      if (line.size() > kLongestLine)
      {
        return where + "longer than " + std::to_string(kLongestLine) + " characters";
      }
      // VTK splits the line as a C string: a NUL byte would end it early.
      if (line.find('\0') != std::string::npos)
      {
        return where + "a NUL byte";
      }
      for (const Property& p : e.properties)
      {
        long long number = 0;
        long long count = 1;
        if (p.countSize > 0)
        {
          if (!words.next(token))
          {
            return where + "no count for list \"" + shadelab::printableText(p.name) + "\"";
          }
          if (!parseToken(token, true, count) || count < 0)
          {
            return where + "list count \"" + shadelab::printableText(token) + "\" is not a count";
          }
          const std::string tooLarge = faceSizeProblem(e, p, count);
          if (!tooLarge.empty())
          {
            return where + tooLarge;
          }
        }
        for (long long k = 0; k < count; ++k)
        {
          if (!words.next(token))
          {
            return where + "fewer values than \"" + shadelab::printableText(p.name) + "\" needs";
          }
          if (!parseToken(token, !p.isFloat, number))
          {
            return where + "\"" + shadelab::printableText(token) + "\" is not a number";
          }
          const std::string finite = isFloatAttribute(e, p) ? slNonFiniteTextProblem(token, true) : std::string();
          if (!finite.empty())
          {
            return where + shadelab::printableText(p.name) + " " + finite;
          }
          if (isFaceIndexList(e, p) && !p.isFloat && (number < 0 || static_cast<unsigned long long>(number) >= vertices))
          {
            return where + indexRange(number, vertices);
          }
        }
      }
    }
  }
  return std::string();
}
} // namespace

std::string slPLYProblem(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  std::string line;
  long lineNumber = 0;
  auto header = [&](std::string& out) {
    if (!std::getline(in, out))
    {
      return false;
    }
    ++lineNumber;
    if (!out.empty() && out.back() == '\r')
    {
      out.pop_back();
    }
    return true;
  };
  if (!header(line) || line != "ply")
  {
    return "line 1: expected \"ply\", found \"" + shadelab::printableText(line) + "\"";
  }
  Format format = Format::Ascii;
  bool haveFormat = false;
  std::vector<Element> elements;
  std::string keyword;
  for (;;)
  {
    if (!header(line))
    {
      return "line " + std::to_string(lineNumber) + ": the header has no end_header";
    }
    const std::string where = "line " + std::to_string(lineNumber) + ": ";
    // VTK's PLY code splits header lines as C strings: a NUL or other
    // control byte corrupts its element table.
    if (line.size() > kLongestLine)
    {
      return where + "header line longer than " + std::to_string(kLongestLine) + " characters";
    }
    for (char c : line)
    {
      const unsigned char u = static_cast<unsigned char>(c);
      if (u < 0x20 && c != '\t')
      {
        return where + "a control byte in the header: \"" + shadelab::printableText(line) + "\"";
      }
    }
    // VTK's PLY code replaces the rest of a line from its first
    // "vertex_index" with "vertex_indices" (so that both names work): a name
    // that only starts so loses the words after it there.
    std::string asRead = line;
    const size_t renamed = asRead.find("vertex_index");
    if (renamed != std::string::npos)
    {
      asRead.replace(renamed, std::string::npos, "vertex_indices");
    }
    std::istringstream words(asRead);
    if (!(words >> keyword))
    {
      // VTK's PLY code takes a line without words for the header's end.
      return where + "a blank line in the header";
    }
    if (keyword == "comment" || keyword == "obj_info")
    {
      continue;
    }
    // The other header lines have a fixed number of words.
    size_t wordCount = 1;
    for (std::string w; words >> w;)
    {
      ++wordCount;
    }
    words.clear();
    words.seekg(0);
    words >> keyword;
    const size_t expected = keyword == "element" || keyword == "format" ? 3
      : keyword == "property"                                          ? (asRead.find(" list ") != std::string::npos ? 5 : 3)
                                                                       : 1;
    if (wordCount != expected)
    {
      return where + "expected " + std::to_string(expected) + " words, found \"" + shadelab::printableText(line) +
        "\"";
    }
    if (keyword == "end_header")
    {
      break;
    }
    if (keyword == "format")
    {
      std::string name, version;
      words >> name >> version;
      haveFormat = true;
      if (name == "ascii")
      {
        format = Format::Ascii;
      }
      else if (name == "binary_little_endian")
      {
        format = Format::Little;
      }
      else if (name == "binary_big_endian")
      {
        format = Format::Big;
      }
      else
      {
        return where + "unknown format \"" + shadelab::printableText(name) + "\"";
      }
    }
    else if (keyword == "element")
    {
      Element e;
      std::string count;
      words >> e.name >> count;
      long long n = -1;
      if (e.name.empty() || !parseToken(count, true, n) || n < 0)
      {
        return where + "element needs a name and a count, found \"" + shadelab::printableText(line) + "\"";
      }
      e.count = static_cast<unsigned long long>(n);
      e.line = lineNumber;
      elements.push_back(e);
    }
    else if (keyword == "property")
    {
      if (elements.empty())
      {
        return where + "property before any element";
      }
      Property p;
      std::string type;
      words >> type;
      if (type == "list")
      {
        std::string countType;
        words >> countType >> type;
        bool countFloat = false;
        p.countSize = typeSize(countType, countFloat, p.countSigned);
        if (p.countSize == 0 || countFloat)
        {
          return where + "list count type \"" + shadelab::printableText(countType) + "\" is not an integer type";
        }
      }
      p.size = typeSize(type, p.isFloat, p.isSigned);
      if (p.size == 0)
      {
        return where + "unknown property type \"" + shadelab::printableText(type) + "\"";
      }
      if (!(words >> p.name))
      {
        return where + "property without a name";
      }
      elements.back().properties.push_back(p);
    }
    else
    {
      return where + "unknown header keyword \"" + shadelab::printableText(keyword) + "\"";
    }
  }
  if (!haveFormat)
  {
    return "the header has no format line";
  }
  // VTK's PLY code allocates an element's property table with its first
  // property: for an element without one, ply_close frees pointers it never
  // set.
  for (const Element& e : elements)
  {
    if (e.properties.empty())
    {
      return "line " + std::to_string(e.line) + ": element \"" + shadelab::printableText(e.name) +
        "\" has no properties";
    }
  }
  // vtkPLYReader looks elements up by name: a second element of the same
  // name is read over the first one's arrays.
  for (size_t i = 0; i < elements.size(); ++i)
  {
    for (size_t j = 0; j < i; ++j)
    {
      if (elements[i].name == elements[j].name)
      {
        return "the header has two elements named \"" + shadelab::printableText(elements[i].name) + "\"";
      }
    }
  }
  // vtkPLYReader looks both elements up and reads x, y, z: without them it
  // follows a bad element table.
  bool haveVertex = false, haveFace = false;
  for (const Element& e : elements)
  {
    bool x = false, y = false, z = false;
    for (const Property& p : e.properties)
    {
      x = x || (p.countSize == 0 && p.name == "x");
      y = y || (p.countSize == 0 && p.name == "y");
      z = z || (p.countSize == 0 && p.name == "z");
    }
    haveVertex = haveVertex || (e.name == "vertex" && x && y && z);
    haveFace = haveFace || e.name == "face";
  }
  if (!haveVertex || !haveFace)
  {
    return "the header needs an element \"vertex\" with properties x, y, z and an element \"face\"";
  }
  // vtkPLYReader reads "vertex" and "face" in file order and skips nothing
  // else: another element before the last of them would be read as its rows.
  // With texture coordinates per face it looks up the face's points while it
  // reads the faces, so the vertices must come first.
  size_t lastRead = 0, vertexAt = 0, faceAt = 0;
  bool faceTexcoords = false;
  for (size_t i = 0; i < elements.size(); ++i)
  {
    if (elements[i].name == "vertex" || elements[i].name == "face")
    {
      lastRead = i;
      (elements[i].name == "vertex" ? vertexAt : faceAt) = i;
    }
    for (const Property& p : elements[i].properties)
    {
      faceTexcoords = faceTexcoords || (elements[i].name == "face" && p.name == "texcoord");
    }
  }
  for (size_t i = 0; i < lastRead; ++i)
  {
    if (elements[i].name != "vertex" && elements[i].name != "face")
    {
      return "element \"" + shadelab::printableText(elements[i].name) + "\" comes before \"" +
        elements[lastRead].name + "\": VTK's PLY reader would read its rows as \"" + elements[lastRead].name + "\"";
    }
  }
  if (faceTexcoords && faceAt < vertexAt)
  {
    return "element \"face\" has texture coordinates and comes before \"vertex\": VTK's PLY reader needs the "
           "vertices first";
  }
  unsigned long long vertices = 0;
  for (const Element& e : elements)
  {
    vertices = e.name == "vertex" ? e.count : vertices;
    // vtkPLYReader frees each face's index list: without one it frees an
    // uninitialised pointer.
    bool hasIndices = false;
    for (const Property& p : e.properties)
    {
      hasIndices = hasIndices || isFaceIndexList(e, p);
    }
    if (e.name == "face" && e.count > 0 && !hasIndices)
    {
      return "element \"face\" has no list property \"vertex_indices\" (or \"vertex_index\")";
    }
  }
  if (format == Format::Ascii)
  {
    return asciiBody(in, lineNumber, elements, vertices);
  }
  return binaryBody(in, (format == Format::Little) != slHostIsLittleEndian(), elements, vertices);
}
