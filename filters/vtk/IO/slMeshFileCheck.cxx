#include "slMeshFileCheck.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <fstream>

#include <sys/stat.h>

namespace
{
unsigned long long fileSize(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary | std::ios::ate);
  const std::streamoff size = in ? static_cast<std::streamoff>(in.tellg()) : 0;
  return size > 0 ? static_cast<unsigned long long>(size) : 0;
}
} // namespace

std::string slReadWholeFile(const std::string& fileName)
{
  // One read into a string of the file's size: a byte-by-byte stream
  // iterator reads an order of magnitude slower.
  std::ifstream in(fileName, std::ios::binary);
  std::string bytes(static_cast<size_t>(fileSize(fileName)), '\0');
  in.read(&bytes[0], static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return bytes;
}

std::string slSTLProblem(const std::string& fileName)
{
  // The test vtkSTLReader makes to choose between ASCII and binary.
  if (vtksys::SystemTools::DetectFileType(fileName.c_str()) != vtksys::SystemTools::FileTypeBinary)
  {
    return std::string();
  }
  // Binary: an 80-byte header, a little-endian triangle count, 50 bytes per
  // triangle. vtkSTLReader reads to the end of the file whatever the count,
  // so a truncated file would load part of its triangles without a word.
  const unsigned long long size = fileSize(fileName);
  std::ifstream in(fileName, std::ios::binary);
  unsigned char header[84];
  if (size < 84 || !in.read(reinterpret_cast<char*>(header), 84))
  {
    return "binary STL shorter than its 84-byte header (" + std::to_string(size) + " bytes)";
  }
  const unsigned long long count = header[80] | header[81] << 8 | header[82] << 16 |
    static_cast<unsigned long long>(header[83]) << 24;
  const unsigned long long needed = 84 + 50 * count;
  if (size < needed)
  {
    return "truncated binary STL: its header announces " + std::to_string(count) + " triangles (" +
      std::to_string(needed) + " bytes), the file has " + std::to_string(size) + " bytes";
  }
  return std::string();
}

std::string slMeshFileProblem(const std::string& fileName, const std::string& ext)
{
  // An empty file is said to be empty, in every format, rather than left to
  // each parser's own wording (which varies with the library's version).
  struct stat status;
  if (stat(fileName.c_str(), &status) == 0 && S_ISREG(status.st_mode) && status.st_size == 0)
  {
    return "the file is empty";
  }
  if (ext == ".obj")
  {
    return slOBJProblem(fileName);
  }
  if (ext == ".ply")
  {
    return slPLYProblem(fileName);
  }
  if (ext == ".stl")
  {
    return slSTLProblem(fileName);
  }
  if (ext == ".gltf" || ext == ".glb")
  {
    return slGLTFProblem(fileName, ext == ".glb");
  }
  if (ext == ".vtp")
  {
    return slVTPProblem(fileName);
  }
  if (ext == ".vtk")
  {
    return slLegacyVTKProblem(fileName);
  }
  return std::string();
}
