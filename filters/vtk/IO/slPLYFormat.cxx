#include "slPLYFormat.h"

#include "slByteOrder.h"
#include "slTextParsing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>
#include <vector>

namespace
{
/// What vtkPLYReader 9.1 makes of a vertex property: a component of the
/// points, normals, texture coordinates or colours, or nothing (Skipped).
enum Role
{
  X,
  Y,
  Z,
  NX,
  NY,
  NZ,
  U,
  V,
  Red,
  Green,
  Blue,
  Alpha,
  Skipped,
  Roles = Skipped
};

/// The role a vertex property's name gives it; -1 for the names
/// vtkPLYReader reads in place of others (its colours from diffuse_red,
/// diffuse_green, diffuse_blue without red, green, blue, and its texture
/// coordinates from texture_u, texture_v without u, v), which the parser
/// declines.
int roleOf(const std::string& name)
{
  static const char* const names[Roles] = { "x", "y", "z", "nx", "ny", "nz", "u", "v", "red", "green", "blue",
    "alpha" };
  for (int r = 0; r < Roles; ++r)
  {
    if (name == names[r])
    {
      return r;
    }
  }
  static const char* const replacements[] = { "diffuse_red", "diffuse_green", "diffuse_blue", "texture_u",
    "texture_v" };
  for (const char* other : replacements)
  {
    if (name == other)
    {
      return -1;
    }
  }
  return Skipped;
}

/// Bytes of a PLY scalar type (0 if unknown), and whether it is a float type.
int typeSize(const std::string& type, bool& isFloat)
{
  static const struct
  {
    const char* name;
    int size;
  } types[] = { { "char", 1 }, { "int8", 1 }, { "uchar", 1 }, { "uint8", 1 }, { "short", 2 }, { "int16", 2 },
    { "ushort", 2 }, { "uint16", 2 }, { "int", 4 }, { "int32", 4 }, { "uint", 4 }, { "uint32", 4 }, { "float", 4 },
    { "float32", 4 }, { "double", 8 }, { "float64", 8 } };
  isFloat = type == "float" || type == "float32" || type == "double" || type == "float64";
  for (const auto& t : types)
  {
    if (type == t.name)
    {
      return t.size;
    }
  }
  return 0;
}

struct VertexProperty
{
  int role;
  int size;           // bytes in a binary row
  bool isFloat;       // of a float type
  std::size_t offset; // in a binary row
};

/// A header of the layouts slParsePLY takes.
struct Layout
{
  bool ascii = false;
  bool bigEndian = false; // of a binary file
  std::size_t bodyAt = 0;
  std::uint64_t vertices = 0, faces = 0;
  std::vector<VertexProperty> properties; // the vertex's, in file order
  int at[Roles];                          // the property of each role, -1 if none
  std::size_t rowBytes = 0;               // of a vertex in a binary file

  Layout() { std::fill(this->at, this->at + Roles, -1); }
  bool has(int role) const { return this->at[role] >= 0; }
  std::size_t offset(int role) const { return this->properties[static_cast<std::size_t>(this->at[role])].offset; }
  int colourComponents() const { return !this->has(Red) ? 0 : this->has(Alpha) ? 4 : 3; }

  /// Adds a vertex property; false if its role is taken or its type is not
  /// one slParsePLY reads for the role: float or double for coordinates,
  /// normals and texture coordinates (vtkPLYReader stores each as a float,
  /// converting a double to the nearest one), uchar for colours. VTK
  /// converts the other types too, integers by rules of their own, which
  /// the parser leaves to it.
  bool add(const std::string& type, const std::string& name)
  {
    bool isFloat = false;
    const int size = typeSize(type, isFloat);
    const int role = roleOf(name);
    if (size == 0 || role < 0 || (role < Skipped && this->has(role)))
    {
      return false;
    }
    if (role < Red ? !isFloat : role < Skipped && type != "uchar" && type != "uint8")
    {
      return false;
    }
    if (role < Skipped)
    {
      this->at[role] = static_cast<int>(this->properties.size());
    }
    this->properties.push_back(VertexProperty{ role, size, isFloat, this->rowBytes });
    this->rowBytes += static_cast<std::size_t>(size);
    return true;
  }

  /// x, y, z, and of the normals, texture coordinates and colours all
  /// components or none (vtkPLYReader ignores a part of them, alpha without
  /// red, green, blue too; the parser declines them).
  bool complete() const
  {
    const auto all = [&](int first, int last) {
      int count = 0;
      for (int r = first; r <= last; ++r)
      {
        count += this->has(r) ? 1 : 0;
      }
      return count == 0 || count == last - first + 1;
    };
    return this->has(X) && this->has(Y) && this->has(Z) && all(NX, NZ) && all(U, V) && all(Red, Blue) &&
      (!this->has(Alpha) || this->has(Red));
  }
};

/// An element count as VTK's PLY code reads it (atoi): digits only, at most
/// INT_MAX.
bool count(const std::string& word, std::uint64_t& value)
{
  if (word.empty() || word.size() > 10 || word.find_first_not_of("0123456789") != std::string::npos)
  {
    return false;
  }
  value = std::strtoull(word.c_str(), nullptr, 10);
  return value <= static_cast<std::uint64_t>(std::numeric_limits<int>::max());
}

/// The longest line, header or ASCII row, that ShadeLab's PLY file check
/// passes (VTK's PLY code reads each into a 4096-byte buffer).
constexpr std::size_t kLongestLine = 4000;

/// Reads the header up to and including its "end_header" line; false
/// unless it is of a layout slParsePLY takes.
bool header(const char* bytes, std::size_t size, Layout& layout)
{
  const std::size_t scan = std::min<std::size_t>(size, 65536);
  const char* nul = static_cast<const char*>(std::memchr(bytes, '\0', scan));
  const std::string head(bytes, nul ? static_cast<std::size_t>(nul - bytes) : scan);
  std::size_t at = head.compare(0, 4, "ply\n") == 0 ? 4 : head.compare(0, 5, "ply\r\n") == 0 ? 5 : 0;
  if (at == 0)
  {
    return false;
  }
  int element = 0; // 1 vertex, 2 face
  bool format = false, faceList = false;
  for (;;)
  {
    const std::size_t newline = head.find('\n', at);
    if (newline == std::string::npos || newline - at > kLongestLine)
    {
      return false;
    }
    // A '\r' before the '\n' ends the line, as VTK's PLY code and the file
    // check read it. That code splits words at spaces and tabs only, a
    // stream at any white space: another control byte would part words for
    // one of them alone.
    const std::size_t end = newline > at && head[newline - 1] == '\r' ? newline - 1 : newline;
    const std::string line = head.substr(at, end - at);
    at = newline + 1;
    if (std::find_if(line.begin(), line.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 && c != '\t'; }) !=
      line.end())
    {
      return false;
    }
    std::istringstream words(line);
    std::string keyword, a, b, c, d, extra;
    words >> keyword;
    if (keyword == "comment" || keyword == "obj_info")
    {
      continue;
    }
    words >> a >> b >> c >> d >> extra;
    if (keyword == "end_header" && a.empty())
    {
      break;
    }
    // The file check counts the words of a property line as those of a list
    // if it holds " list " (spaces, not tabs).
    const bool listLine = line.find(" list ") != std::string::npos;
    // VTK's PLY code replaces the rest of a line from "vertex_index" on with
    // "vertex_indices", so that either names the faces' indices; another
    // line it would change is declined.
    if (keyword == "property" && element == 2 && !faceList && listLine && a == "list" && (b == "uchar" || b == "uint8") &&
      (c == "int" || c == "int32" || c == "uint" || c == "uint32") && (d == "vertex_indices" || d == "vertex_index") &&
      extra.empty())
    {
      faceList = true;
      continue;
    }
    if (line.find("vertex_index") != std::string::npos)
    {
      return false;
    }
    const bool knownFormat = a == "ascii" || a == "binary_little_endian" || a == "binary_big_endian";
    if (keyword == "format" && !format && element == 0 && knownFormat && b == "1.0" && c.empty())
    {
      format = true;
      layout.ascii = a == "ascii";
      layout.bigEndian = a == "binary_big_endian";
    }
    else if (keyword == "element" && c.empty() && format && element == 0 && a == "vertex" && count(b, layout.vertices))
    {
      element = 1;
    }
    else if (keyword == "element" && c.empty() && element == 1 && a == "face" && count(b, layout.faces))
    {
      element = 2;
    }
    else if (!(keyword == "property" && element == 1 && !listLine && !b.empty() && c.empty() && layout.add(a, b)))
    {
      return false;
    }
  }
  layout.bodyAt = at;
  return element == 2 && faceList && layout.complete();
}

/// The float vtkPLYReader stores for a binary float or double @p at
/// (@p bytes 4 or 8): the float itself, or the double converted to the
/// nearest float. False for a double beyond the largest float or NaN, whose
/// conversion C++ leaves undefined: the parser leaves such a file to VTK.
template <bool Swap>
bool binaryFloat(const char* at, int bytes, float& value)
{
  if (bytes == 4)
  {
    const std::uint32_t bits = slLoadUnsigned<Swap, std::uint32_t>(at);
    std::memcpy(&value, &bits, 4);
    return true;
  }
  const std::uint64_t bits = slLoadUnsigned<Swap, std::uint64_t>(at);
  double wide;
  std::memcpy(&wide, &bits, 8);
  if (!(std::fabs(wide) <= static_cast<double>(std::numeric_limits<float>::max())))
  {
    return false;
  }
  value = static_cast<float>(wide);
  return true;
}

/// The vertices of a binary file, rows of layout.rowBytes bytes from
/// @p rows; false if a double has no float (binaryFloat).
template <bool Swap>
bool binaryVertices(const char* rows, const Layout& layout, slMeshArrays& mesh)
{
  const std::size_t n = static_cast<std::size_t>(layout.vertices);
  const std::size_t rowBytes = layout.rowBytes;
  std::size_t offset[Roles] = {};
  int bytes[Roles] = {};
  for (int r = 0; r < Roles; ++r)
  {
    offset[r] = layout.has(r) ? layout.offset(r) : 0;
    bytes[r] = layout.has(r) ? layout.properties[static_cast<std::size_t>(layout.at[r])].size : 0;
  }
  bool ok = true;
  const auto copy = [&](float* to, const char* row, int first, int components) {
    for (int k = 0; k < components; ++k)
    {
      ok = binaryFloat<Swap>(row + offset[first + k], bytes[first + k], to[k]) && ok;
    }
  };
  const std::size_t colours = static_cast<std::size_t>(mesh.colourComponents);
  for (std::size_t i = 0; i < n; ++i)
  {
    const char* row = rows + i * rowBytes;
    copy(&mesh.points[3 * i], row, X, 3);
    if (layout.has(NX))
    {
      copy(&mesh.normals[3 * i], row, NX, 3);
    }
    if (layout.has(U))
    {
      copy(&mesh.tcoords[2 * i], row, U, 2);
    }
    for (std::size_t k = 0; k < colours; ++k)
    {
      mesh.colours[colours * i + k] = static_cast<unsigned char>(row[offset[Red + k]]);
    }
  }
  return ok;
}

/// The faces of a binary file from @p at: false unless each is a count byte
/// of 3 or more and as many 4-byte indices of existing vertices, and the
/// last ends the file.
template <bool Swap>
bool binaryFaces(const char* bytes, std::size_t size, std::size_t at, const Layout& layout, slMeshArrays& mesh)
{
  // At least 13 bytes each.
  if (layout.faces > (size - at) / 13)
  {
    return false;
  }
  const std::size_t faces = static_cast<std::size_t>(layout.faces);
  mesh.offsets.resize(faces + 1);
  mesh.offsets[0] = 0;
  mesh.connectivity.reserve(faces * 3);
  for (std::size_t f = 0; f < faces; ++f)
  {
    if (at >= size)
    {
      return false;
    }
    const unsigned count = static_cast<unsigned char>(bytes[at++]);
    if (count < 3 || static_cast<std::size_t>(count) * 4 > size - at)
    {
      return false;
    }
    for (unsigned k = 0; k < count; ++k, at += 4)
    {
      const std::uint32_t index = slLoadUnsigned<Swap, std::uint32_t>(bytes + at);
      // Signed or unsigned alike: an index of 2^31 or more is out of range
      // either way.
      if (index >= layout.vertices)
      {
        return false;
      }
      mesh.connectivity.push_back(static_cast<std::int64_t>(index));
    }
    mesh.offsets[f + 1] = static_cast<std::int64_t>(mesh.connectivity.size());
  }
  return at == size;
}

/// What one stretch of an ASCII body's lines holds besides its vertices,
/// which go straight into the mesh.
struct Stretch
{
  std::uint64_t firstRow = 0; // the row of its first line
  std::uint64_t lines = 0;    // newlines in it
  std::vector<std::int64_t> corners;
  std::vector<std::int64_t> faceEnds; // corners up to each face's end
  bool ok = true;
};

/// One vertex row of an ASCII file into vertex @p i of @p mesh, read as
/// VTK's PLY code reads it (atof, then a cast, for a float): false unless
/// it holds every property's value and nothing else. Values of properties
/// vtkPLYReader ignores must be numbers too, as the file check wants them.
bool asciiVertex(slTextCursor& c, std::size_t i, const Layout& layout, slMeshArrays& mesh)
{
  float values[U + 2];
  unsigned char rgba[4];
  for (const VertexProperty& p : layout.properties)
  {
    if (p.role < Red)
    {
      if (!c.numberViaDouble(values[p.role]))
      {
        return false;
      }
    }
    else if (p.role < Skipped)
    {
      std::uint64_t value;
      if (!c.unsignedInteger(value, 255))
      {
        return false;
      }
      rgba[p.role - Red] = static_cast<unsigned char>(value);
    }
    else if (p.isFloat)
    {
      double value;
      if (!c.number(value))
      {
        return false;
      }
    }
    else
    {
      std::int64_t value;
      if (!c.integer(value))
      {
        return false;
      }
    }
  }
  if (!c.done())
  {
    return false;
  }
  std::memcpy(&mesh.points[3 * i], values + X, 3 * sizeof(float));
  if (layout.has(NX))
  {
    std::memcpy(&mesh.normals[3 * i], values + NX, 3 * sizeof(float));
  }
  if (layout.has(U))
  {
    std::memcpy(&mesh.tcoords[2 * i], values + U, 2 * sizeof(float));
  }
  const std::size_t colours = static_cast<std::size_t>(mesh.colourComponents);
  if (colours > 0)
  {
    std::memcpy(&mesh.colours[colours * i], rgba, colours);
  }
  return true;
}

/// One face row of an ASCII file: a count of 3 to 255, as many indices of
/// existing vertices, nothing else.
bool asciiFace(slTextCursor& c, const Layout& layout, Stretch& stretch)
{
  std::uint64_t count, index;
  if (layout.vertices == 0 || !c.unsignedInteger(count, 255) || count < 3)
  {
    return false;
  }
  for (std::uint64_t k = 0; k < count; ++k)
  {
    if (!c.unsignedInteger(index, layout.vertices - 1))
    {
      return false;
    }
    stretch.corners.push_back(static_cast<std::int64_t>(index));
  }
  stretch.faceEnds.push_back(static_cast<std::int64_t>(stretch.corners.size()));
  return c.done();
}

/// The lines [@p begin, @p end) of an ASCII body, from row stretch.firstRow
/// on: one row per line, every row ending in a newline (VTK's PLY code
/// finds none in a last line without one), of at most kLongestLine bytes,
/// and blank lines only after the last row.
bool asciiLines(const char* begin, const char* end, const Layout& layout, slMeshArrays& mesh, Stretch& stretch)
{
  const std::uint64_t rows = layout.vertices + layout.faces;
  std::uint64_t row = stretch.firstRow;
  for (const char* line = begin; line < end; ++row)
  {
    const char* newline = static_cast<const char*>(std::memchr(line, '\n', static_cast<std::size_t>(end - line)));
    if (newline ? static_cast<std::size_t>(newline - line) > kLongestLine : row < rows)
    {
      return false;
    }
    const char* next = newline ? newline : end;
    slTextCursor c{ line, newline && next > line && next[-1] == '\r' ? next - 1 : next };
    line = next + 1;
    if (row < layout.vertices ? !asciiVertex(c, static_cast<std::size_t>(row), layout, mesh)
        : row < rows          ? !asciiFace(c, layout, stretch)
                              : !c.done())
    {
      return false;
    }
  }
  return true;
}

/// Sizes the vertex arrays of @p mesh for the layout's vertices and
/// properties; returns the number of vertices.
std::size_t sizeVertexArrays(const Layout& layout, slMeshArrays& mesh)
{
  const std::size_t n = static_cast<std::size_t>(layout.vertices);
  mesh.points.resize(3 * n);
  mesh.normals.resize(layout.has(NX) ? 3 * n : 0);
  mesh.tcoords.resize(layout.has(U) ? 2 * n : 0);
  mesh.colours.resize(static_cast<std::size_t>(mesh.colourComponents) * n);
  return n;
}

/// The body of an ASCII file, its lines split among @p threads threads: a
/// first pass counts each stretch's lines, which tells the rows it holds.
bool asciiBody(const char* bytes, std::size_t size, const Layout& layout, slMeshArrays& mesh, int threads)
{
  const char* text = bytes + layout.bodyAt;
  const std::size_t length = size - layout.bodyAt;
  const std::vector<const char*> bounds = slLineStretches(text, length, slTextStretchCount(length, threads));
  std::vector<Stretch> stretches(bounds.size() - 1);
  slRunEach(stretches.size(), [&](std::size_t k) {
    stretches[k].lines = static_cast<std::uint64_t>(slCountLines(bounds[k], bounds[k + 1]));
  });
  std::uint64_t lines = 0;
  for (Stretch& s : stretches)
  {
    s.firstRow = lines;
    lines += s.lines;
  }
  // Every row ends in a newline; the arrays are then no larger than the file.
  if (lines < layout.vertices + layout.faces)
  {
    return false;
  }
  sizeVertexArrays(layout, mesh);
  slRunEach(stretches.size(),
    [&](std::size_t k) { stretches[k].ok = asciiLines(bounds[k], bounds[k + 1], layout, mesh, stretches[k]); });
  // The faces joined in order, each stretch's on a thread of its own.
  std::vector<std::size_t> firstFace(stretches.size() + 1, 0), firstCorner(stretches.size() + 1, 0);
  for (std::size_t k = 0; k < stretches.size(); ++k)
  {
    if (!stretches[k].ok)
    {
      return false;
    }
    firstFace[k + 1] = firstFace[k] + stretches[k].faceEnds.size();
    firstCorner[k + 1] = firstCorner[k] + stretches[k].corners.size();
  }
  if (stretches.size() == 1)
  {
    mesh.connectivity = std::move(stretches[0].corners);
  }
  else
  {
    mesh.connectivity.resize(firstCorner.back());
  }
  mesh.offsets.resize(firstFace.back() + 1);
  mesh.offsets[0] = 0;
  slRunEach(stretches.size(), [&](std::size_t k) {
    const Stretch& s = stretches[k];
    if (stretches.size() > 1 && !s.corners.empty())
    {
      std::memcpy(&mesh.connectivity[firstCorner[k]], s.corners.data(), s.corners.size() * sizeof(std::int64_t));
    }
    for (std::size_t f = 0; f < s.faceEnds.size(); ++f)
    {
      mesh.offsets[firstFace[k] + f + 1] = static_cast<std::int64_t>(firstCorner[k]) + s.faceEnds[f];
    }
  });
  return true;
}

void put(std::string& out, const void* value, std::size_t n)
{
  out.append(static_cast<const char*>(value), n);
}
} // namespace

bool slParsePLY(const char* bytes, std::size_t size, slMeshArrays& mesh, int threads)
{
  Layout layout;
  if (!header(bytes, size, layout))
  {
    return false;
  }
  mesh = slMeshArrays();
  mesh.colourComponents = layout.colourComponents();
  if (layout.ascii)
  {
    return asciiBody(bytes, size, layout, mesh, threads);
  }
  if (layout.vertices > (size - layout.bodyAt) / layout.rowBytes)
  {
    return false;
  }
  const std::size_t n = sizeVertexArrays(layout, mesh);
  const std::size_t facesAt = layout.bodyAt + n * layout.rowBytes;
  if (layout.bigEndian == slHostIsLittleEndian())
  {
    return binaryVertices<true>(bytes + layout.bodyAt, layout, mesh) &&
      binaryFaces<true>(bytes, size, facesAt, layout, mesh);
  }
  return binaryVertices<false>(bytes + layout.bodyAt, layout, mesh) &&
    binaryFaces<false>(bytes, size, facesAt, layout, mesh);
}

bool slFormatPLY(const slMeshView& mesh, std::string& out)
{
  if (!slHostIsLittleEndian())
  {
    return false;
  }
  // Counts are bytes: VTK's PLY reader reads no more (nor does its writer).
  for (std::int64_t p = 0; p < mesh.numberOfPolygons; ++p)
  {
    if (mesh.offsets[static_cast<std::size_t>(p + 1)] - mesh.offsets[static_cast<std::size_t>(p)] > 255)
    {
      return false;
    }
  }
  std::string head = "ply\nformat binary_little_endian 1.0\ncomment written by ShadeLab\nelement vertex " +
    std::to_string(mesh.numberOfPoints) + "\nproperty float x\nproperty float y\nproperty float z\n";
  if (mesh.normals.data)
  {
    head += "property float nx\nproperty float ny\nproperty float nz\n";
  }
  if (mesh.tcoords.data)
  {
    head += "property float u\nproperty float v\n";
  }
  const std::size_t colourBytes = mesh.colours ? static_cast<std::size_t>(mesh.colourComponents) : 0;
  static const char* const colourNames[] = { "red", "green", "blue", "alpha" };
  for (std::size_t k = 0; k < colourBytes; ++k)
  {
    head += std::string("property uchar ") + colourNames[k] + "\n";
  }
  head += "element face " + std::to_string(mesh.numberOfPolygons) + "\nproperty list uchar int vertex_indices\nend_header\n";
  const std::size_t columns = 3 + (mesh.normals.data ? 3 : 0) + (mesh.tcoords.data ? 2 : 0);
  const std::size_t corners = static_cast<std::size_t>(mesh.offsets[static_cast<std::size_t>(mesh.numberOfPolygons)]);
  out.reserve(out.size() + head.size() + static_cast<std::size_t>(mesh.numberOfPoints) * (columns * 4 + colourBytes) +
    static_cast<std::size_t>(mesh.numberOfPolygons) + corners * 4);
  out += head;
  for (std::int64_t i = 0; i < mesh.numberOfPoints; ++i)
  {
    float row[8];
    std::size_t c = 0;
    const std::size_t p = static_cast<std::size_t>(i);
    for (int k = 0; k < 3; ++k)
    {
      row[c++] = static_cast<float>(mesh.points[3 * p + static_cast<std::size_t>(k)]);
    }
    for (int k = 0; mesh.normals.data && k < 3; ++k)
    {
      row[c++] = static_cast<float>(mesh.normals[3 * p + static_cast<std::size_t>(k)]);
    }
    for (int k = 0; mesh.tcoords.data && k < 2; ++k)
    {
      row[c++] = static_cast<float>(mesh.tcoords[2 * p + static_cast<std::size_t>(k)]);
    }
    put(out, row, c * 4);
    if (colourBytes > 0)
    {
      put(out, mesh.colours + colourBytes * p, colourBytes);
    }
  }
  for (std::int64_t p = 0; p < mesh.numberOfPolygons; ++p)
  {
    const std::int64_t first = mesh.offsets[static_cast<std::size_t>(p)], last = mesh.offsets[static_cast<std::size_t>(p + 1)];
    out += static_cast<char>(static_cast<unsigned char>(last - first));
    for (std::int64_t k = first; k < last; ++k)
    {
      const std::int32_t index = static_cast<std::int32_t>(mesh.connectivity[static_cast<std::size_t>(k)]);
      put(out, &index, 4);
    }
  }
  return true;
}
