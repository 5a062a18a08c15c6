#include "slPLYFormat.h"

#include <cstring>
#include <sstream>

namespace
{
bool hostIsLittle()
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

/// The vertex properties read, by their column in a row of floats.
struct VertexLayout
{
  int x = -1, y = -1, z = -1, nx = -1, ny = -1, nz = -1, u = -1, v = -1;
  int columns = 0;

  int* column(const std::string& name)
  {
    static const char* const names[] = { "x", "y", "z", "nx", "ny", "nz", "u", "v" };
    int* slots[] = { &x, &y, &z, &nx, &ny, &nz, &u, &v };
    for (int k = 0; k < 8; ++k)
    {
      if (name == names[k])
      {
        return slots[k];
      }
    }
    return nullptr;
  }
};

/// Reads the header up to and including "end_header\n"; false unless it is
/// of the one layout slParsePLY takes.
bool header(const char* bytes, std::size_t size, std::size_t& bodyAt, VertexLayout& layout, std::uint64_t& vertices,
  std::uint64_t& faces, int& indexBytes)
{
  const char* end = static_cast<const char*>(std::memchr(bytes, '\0', size < 65536 ? size : 65536));
  const std::string head(bytes, end ? static_cast<std::size_t>(end - bytes) : (size < 65536 ? size : 65536));
  const std::size_t stop = head.find("\nend_header\n");
  if (head.compare(0, 4, "ply\n") != 0 || stop == std::string::npos)
  {
    return false;
  }
  bodyAt = stop + 12;
  // VTK's PLY code splits header words at spaces and tabs only, and these
  // streams at any white space: a form feed would part words for one of
  // them alone.
  for (std::size_t i = 0; i < stop; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(head[i]);
    if (c < 0x20 && c != '\n' && c != '\t')
    {
      return false;
    }
  }
  std::istringstream lines(head.substr(4, stop - 4 + 1));
  int element = 0; // 1 vertex, 2 face
  bool format = false, faceList = false;
  for (std::string line; std::getline(lines, line);)
  {
    std::istringstream words(line);
    std::string keyword, a, b, c, d, extra;
    words >> keyword;
    if (keyword == "comment" || keyword == "obj_info")
    {
      continue;
    }
    words >> a >> b >> c >> d >> extra;
    if (keyword == "format" && !format && element == 0 && a == "binary_little_endian" && b == "1.0" && c.empty())
    {
      format = true;
    }
    else if (keyword == "element" && c.empty() && format && element == 0 && a == "vertex")
    {
      element = 1;
      vertices = std::strtoull(b.c_str(), nullptr, 10);
      if (b.find_first_not_of("0123456789") != std::string::npos || b.empty() || b.size() > 12)
      {
        return false;
      }
    }
    else if (keyword == "element" && c.empty() && element == 1 && a == "face")
    {
      element = 2;
      faces = std::strtoull(b.c_str(), nullptr, 10);
      if (b.find_first_not_of("0123456789") != std::string::npos || b.empty() || b.size() > 12)
      {
        return false;
      }
    }
    else if (keyword == "property" && element == 1 && a == "float" && c.empty())
    {
      int* slot = layout.column(b);
      if (!slot || *slot >= 0)
      {
        return false;
      }
      *slot = layout.columns++;
    }
    else if (keyword == "property" && element == 2 && !faceList && a == "list" && (b == "uchar" || b == "uint8") &&
      (c == "int" || c == "int32" || c == "uint" || c == "uint32") && d == "vertex_indices" && extra.empty())
    {
      faceList = true;
      indexBytes = 4;
    }
    else
    {
      return false;
    }
  }
  const bool normals = layout.nx >= 0 || layout.ny >= 0 || layout.nz >= 0;
  const bool tcoords = layout.u >= 0 || layout.v >= 0;
  return element == 2 && faceList && layout.x >= 0 && layout.y >= 0 && layout.z >= 0 &&
    (!normals || (layout.nx >= 0 && layout.ny >= 0 && layout.nz >= 0)) && (!tcoords || (layout.u >= 0 && layout.v >= 0));
}

void put(std::string& out, const void* value, std::size_t n)
{
  out.append(static_cast<const char*>(value), n);
}
} // namespace

bool slParsePLY(const char* bytes, std::size_t size, slMeshArrays& mesh)
{
  std::size_t at = 0;
  VertexLayout layout;
  std::uint64_t vertices = 0, faces = 0;
  int indexBytes = 0;
  if (!hostIsLittle() || !header(bytes, size, at, layout, vertices, faces, indexBytes))
  {
    return false;
  }
  const std::size_t rowBytes = static_cast<std::size_t>(layout.columns) * 4;
  if (vertices > (size - at) / rowBytes)
  {
    return false;
  }
  const std::size_t n = static_cast<std::size_t>(vertices);
  mesh = slMeshArrays();
  mesh.points.resize(3 * n);
  mesh.normals.resize(layout.nx >= 0 ? 3 * n : 0);
  mesh.tcoords.resize(layout.u >= 0 ? 2 * n : 0);
  const char* rows = bytes + at;
  auto column = [&](std::size_t i, int c) {
    float value;
    std::memcpy(&value, rows + i * rowBytes + static_cast<std::size_t>(c) * 4, 4);
    return value;
  };
  for (std::size_t i = 0; i < n; ++i)
  {
    mesh.points[3 * i] = column(i, layout.x);
    mesh.points[3 * i + 1] = column(i, layout.y);
    mesh.points[3 * i + 2] = column(i, layout.z);
    if (layout.nx >= 0)
    {
      mesh.normals[3 * i] = column(i, layout.nx);
      mesh.normals[3 * i + 1] = column(i, layout.ny);
      mesh.normals[3 * i + 2] = column(i, layout.nz);
    }
    if (layout.u >= 0)
    {
      mesh.tcoords[2 * i] = column(i, layout.u);
      mesh.tcoords[2 * i + 1] = column(i, layout.v);
    }
  }
  at += n * rowBytes;
  // Faces: a count byte, then the indices; at least 13 bytes each.
  if (faces > (size - at) / 13)
  {
    return false;
  }
  mesh.offsets.resize(static_cast<std::size_t>(faces) + 1);
  mesh.offsets[0] = 0;
  mesh.connectivity.reserve(static_cast<std::size_t>(faces) * 3);
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
      std::uint32_t index;
      std::memcpy(&index, bytes + at, 4);
      // Signed or unsigned alike: an index of 2^31 or more is out of range
      // either way.
      if (index >= vertices)
      {
        return false;
      }
      mesh.connectivity.push_back(static_cast<std::int64_t>(index));
    }
    mesh.offsets[f + 1] = static_cast<std::int64_t>(mesh.connectivity.size());
  }
  return at == size;
}

bool slFormatPLY(const slMeshView& mesh, std::string& out)
{
  if (!hostIsLittle())
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
