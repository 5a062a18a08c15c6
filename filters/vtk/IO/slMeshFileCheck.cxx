#include "slMeshFileCheck.h"

#include "shadelab/PrintableText.h"

#include <vtkBase64InputStream.h>
#include <vtkNew.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

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

namespace
{
/// The value of attribute @p name in the tag text @p tag, or "".
std::string attribute(const std::string& tag, const std::string& name)
{
  const std::string key = " " + name + "=\"";
  const size_t at = tag.find(key);
  if (at == std::string::npos)
  {
    return std::string();
  }
  const size_t begin = at + key.size();
  const size_t end = tag.find('"', begin);
  return end == std::string::npos ? std::string() : tag.substr(begin, end - begin);
}

/// @p bytes bytes decoded from the base64 text of @p text at @p begin, as
/// vtkXMLDataParser decodes them (vtkBase64InputStream: four characters at a
/// time, as they are, padding and bytes outside the alphabet included);
/// fewer if the text ends first.
std::string base64(const std::string& text, size_t begin, size_t bytes)
{
  if (begin >= text.size())
  {
    return std::string();
  }
  std::istringstream in(text.substr(begin, (bytes + 2) / 3 * 4));
  vtkNew<vtkBase64InputStream> stream;
  stream->SetStream(&in);
  stream->StartReading();
  std::string out(bytes, '\0');
  const size_t read = stream->Read(&out[0], bytes);
  stream->EndReading();
  out.resize(read);
  return out;
}

unsigned long long word(const std::string& bytes, size_t at, int size, bool little)
{
  unsigned long long v = 0;
  for (int b = 0; b < size; ++b)
  {
    const unsigned char c = static_cast<unsigned char>(bytes[at + static_cast<size_t>(little ? size - 1 - b : b)]);
    v = v << 8 | c;
  }
  return v;
}
} // namespace

std::string slXMLCountsProblem(const std::string& fileName)
{
  // Every point and cell takes at least one value in the file, and zlib,
  // the densest compression VTK's XML writer uses, packs at most 1032 bytes
  // into one: a count beyond that is a header VTK would allocate for.
  const unsigned long long size = fileSize(fileName);
  const unsigned long long limit = 1032 * (size + 1);
  std::ifstream in(fileName, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t appended = bytes.find("<AppendedData");
  const std::string text = bytes.substr(0, appended);
  static const char* const names[] = { "NumberOfPoints=\"", "NumberOfVerts=\"", "NumberOfLines=\"",
    "NumberOfStrips=\"", "NumberOfPolys=\"", "NumberOfTuples=\"", "NumberOfComponents=\"" };
  for (const char* name : names)
  {
    for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1))
    {
      const size_t begin = at + std::strlen(name);
      unsigned long long value = 0;
      size_t i = begin;
      for (; i < text.size() && i < begin + 21 && text[i] >= '0' && text[i] <= '9'; ++i)
      {
        value = value * 10 + static_cast<unsigned long long>(text[i] - '0');
      }
      if (i - begin > 20 || value > limit)
      {
        const std::string attributeName(name, std::strlen(name) - 2);
        return attributeName + "=" + text.substr(begin, std::min<size_t>(i - begin, 20)) +
          " is more than a file of " + std::to_string(size) + " bytes can hold";
      }
    }
  }

  // Compressed arrays start with a header: the number of blocks, the block
  // size, the last block's size, then each block's compressed size. VTK
  // allocates what the first two say: both must fit the file.
  const size_t fileTag = text.find("<VTKFile");
  const std::string vtkFile = fileTag == std::string::npos ? std::string() : text.substr(fileTag, text.find('>', fileTag) - fileTag);
  if (attribute(vtkFile, "compressor").empty())
  {
    return std::string();
  }
  const int wordSize = attribute(vtkFile, "header_type") == "UInt64" ? 8 : 4;
  const bool little = attribute(vtkFile, "byte_order") != "BigEndian";
  // Appended data starts after "_"; offsets count its bytes, or its
  // characters when it is base64 (each array's header encoded on its own).
  size_t appendedStart = std::string::npos;
  bool appendedBase64 = false;
  if (appended != std::string::npos)
  {
    const size_t close = bytes.find('>', appended);
    size_t underscore = close == std::string::npos ? bytes.size() : close + 1;
    while (underscore < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[underscore])))
    {
      ++underscore;
    }
    const std::string tag = bytes.substr(appended, close == std::string::npos ? 0 : close - appended);
    if (underscore >= bytes.size() || bytes[underscore] != '_')
    {
      // VTK's writers put "_" first; vtkXMLDataParser takes the data from
      // the first character after the tag's white space, "_" or not.
      return "the AppendedData element's data does not start with \"_\"";
    }
    appendedStart = underscore + 1;
    appendedBase64 = attribute(tag, "encoding") == "base64";
  }
  for (size_t at = text.find("<DataArray"); at != std::string::npos; at = text.find("<DataArray", at + 1))
  {
    const size_t close = text.find('>', at);
    if (close == std::string::npos)
    {
      break;
    }
    const std::string tag = text.substr(at, close - at);
    const std::string format = attribute(tag, "format");
    // The first @p n bytes of the array's compression header ("" if its data
    // does not start within the file).
    bool located = false; // the array's data starts within the file
    size_t dataAt = 0;
    if (format == "binary")
    {
      // vtkXMLDataParser starts inline data at its first non-space character.
      located = true;
      dataAt = text.find_first_not_of(" \t\r\n", close + 1);
      dataAt = dataAt == std::string::npos ? text.size() : dataAt;
    }
    else if (format == "appended")
    {
      const unsigned long long offset = std::strtoull(attribute(tag, "offset").c_str(), nullptr, 10);
      if (appendedStart != std::string::npos && offset < bytes.size() - appendedStart)
      {
        located = true;
        dataAt = appendedStart + static_cast<size_t>(offset);
      }
    }
    const bool base64Encoded = format == "binary" || (format == "appended" && appendedBase64);
    auto headerBytes = [&](size_t n) -> std::string {
      if (!located)
      {
        return std::string();
      }
      return base64Encoded ? base64(format == "binary" ? text : bytes, dataAt, n) : bytes.substr(dataAt, n);
    };
    const std::string name = shadelab::printableText(attribute(tag, "Name"));
    const std::string header = headerBytes(static_cast<size_t>(3 * wordSize));
    if (header.size() < static_cast<size_t>(3 * wordSize))
    {
      if (base64Encoded && (located || !header.empty()))
      {
        // vtkBase64InputStream decodes what it is given, padding and bytes
        // outside the alphabet included, and would take a header from them.
        return "DataArray \"" + name + "\": its compression header is not " + std::to_string(3 * wordSize) +
          " bytes of base64";
      }
      continue; // VTK finds the data missing and says so
    }
    const unsigned long long blocks = word(header, 0, wordSize, little);
    const unsigned long long blockSize = word(header, static_cast<size_t>(wordSize), wordSize, little);
    const unsigned long long lastBlockSize = word(header, static_cast<size_t>(2 * wordSize), wordSize, little);
    if (lastBlockSize > blockSize && blockSize <= limit)
    {
      // VTK allocates the last block's size as it is; no block is larger than the block size.
      return "DataArray \"" + name + "\": its compression header's last block of " + std::to_string(lastBlockSize) +
        " bytes is larger than its block size of " + std::to_string(blockSize);
    }
    if (blocks == 0 && lastBlockSize != 0)
    {
      // VTK takes the data's size as (blocks - 1) * block size + the last
      // block's: with no blocks that wraps around, and VTK reads block 0 of
      // a list it never allocated.
      return "DataArray \"" + name + "\": its compression header declares no blocks but a last block of " +
        std::to_string(lastBlockSize) + " bytes";
    }
    if (blocks > size / static_cast<unsigned long long>(wordSize) || blockSize > limit)
    {
      return "DataArray \"" + name + "\": its compression header declares " + std::to_string(blocks) +
        " blocks of " + std::to_string(blockSize) + " bytes, more than a file of " + std::to_string(size) +
        " bytes can hold";
    }
    // Then each block's compressed size, which VTK allocates to read it.
    const size_t fullSize = static_cast<size_t>((3 + blocks) * static_cast<unsigned long long>(wordSize));
    const std::string full = headerBytes(fullSize);
    if (full.size() < fullSize)
    {
      if (base64Encoded)
      {
        return "DataArray \"" + name + "\": its compression header's " + std::to_string(blocks) +
          " block sizes are not " + std::to_string(fullSize) + " bytes of base64";
      }
      continue; // VTK finds the header cut short and says so
    }
    for (unsigned long long b = 0; b < blocks; ++b)
    {
      const unsigned long long compressed = word(full, static_cast<size_t>((3 + b) * wordSize), wordSize, little);
      if (compressed > size)
      {
        return "DataArray \"" + name + "\": its compression header gives block " + std::to_string(b) + " " +
          std::to_string(compressed) + " compressed bytes, more than the file's " + std::to_string(size);
      }
    }
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
    return slXMLCountsProblem(fileName);
  }
  if (ext == ".vtk")
  {
    return slLegacyVTKProblem(fileName);
  }
  return std::string();
}
