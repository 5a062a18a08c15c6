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
#include <utility>
#include <vector>

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
bool isXMLSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

/// The end of the start tag that begins at @p at in @p text: the position
/// of its closing '>' outside quoted values (npos if the text ends first).
size_t tagEnd(const std::string& text, size_t at)
{
  char quote = 0;
  for (size_t i = at; i < text.size(); ++i)
  {
    const char c = text[i];
    if (quote)
    {
      quote = c == quote ? 0 : quote;
    }
    else if (c == '"' || c == '\'')
    {
      quote = c;
    }
    else if (c == '>')
    {
      return i;
    }
  }
  return std::string::npos;
}

/// @p value with its character references and predefined entities decoded
/// and each white space character made a space, as expat hands attribute
/// values to VTK's XML parser.
std::string xmlAttributeValue(const std::string& value)
{
  std::string out;
  for (size_t i = 0; i < value.size(); ++i)
  {
    const char c = value[i];
    const size_t semicolon = c == '&' ? value.find(';', i) : std::string::npos;
    if (semicolon == std::string::npos)
    {
      out += isXMLSpace(c) ? ' ' : c;
      continue;
    }
    const std::string entity = value.substr(i + 1, semicolon - i - 1);
    static const char* const names[][2] = { { "lt", "<" }, { "gt", ">" }, { "amp", "&" }, { "quot", "\"" },
      { "apos", "'" } };
    bool known = false;
    for (const auto& name : names)
    {
      if (entity == name[0])
      {
        out += name[1];
        known = true;
      }
    }
    if (!known && entity.size() > 1 && entity[0] == '#')
    {
      const bool hex = entity[1] == 'x';
      const unsigned long code = std::strtoul(entity.c_str() + (hex ? 2 : 1), nullptr, hex ? 16 : 10);
      // A character outside ASCII cannot be part of a number or of one of
      // VTK's keywords: '?' stands for it.
      out += code > 0 && code < 128 ? static_cast<char>(code) : '?';
      known = true;
    }
    if (!known)
    {
      out += value.substr(i, semicolon - i + 1);
    }
    i = semicolon;
  }
  return out;
}

/// A start tag's attributes: names and values, in the tag's order.
using XMLAttributes = std::vector<std::pair<std::string, std::string>>;

/// The attributes of the start tag @p tag ("<Name" up to its '>'), read as
/// expat reads them: white space around '=', single or double quotes,
/// references decoded. Ends at the first thing expat would refuse (it then
/// refuses the file).
XMLAttributes xmlAttributes(const std::string& tag)
{
  XMLAttributes attributes;
  size_t i = 1;
  while (i < tag.size() && !isXMLSpace(tag[i]) && tag[i] != '/')
  {
    ++i; // the element's name
  }
  const auto skipSpace = [&] {
    while (i < tag.size() && isXMLSpace(tag[i]))
    {
      ++i;
    }
  };
  while (i < tag.size())
  {
    while (i < tag.size() && (isXMLSpace(tag[i]) || tag[i] == '/'))
    {
      ++i;
    }
    const size_t nameBegin = i;
    while (i < tag.size() && !isXMLSpace(tag[i]) && tag[i] != '=')
    {
      ++i;
    }
    const size_t nameEnd = i;
    skipSpace();
    if (i >= tag.size() || tag[i] != '=')
    {
      break;
    }
    ++i;
    skipSpace();
    const size_t close = i < tag.size() && (tag[i] == '"' || tag[i] == '\'') ? tag.find(tag[i], i + 1) : std::string::npos;
    if (close == std::string::npos)
    {
      break;
    }
    attributes.emplace_back(tag.substr(nameBegin, nameEnd - nameBegin), xmlAttributeValue(tag.substr(i + 1, close - i - 1)));
    i = close + 1;
  }
  return attributes;
}

/// The value of attribute @p name among @p attributes, or null.
const std::string* findAttribute(const XMLAttributes& attributes, const std::string& name)
{
  for (const auto& attribute : attributes)
  {
    if (attribute.first == name)
    {
      return &attribute.second;
    }
  }
  return nullptr;
}

/// The value of attribute @p name in the start tag @p tag, or "".
std::string attribute(const std::string& tag, const std::string& name)
{
  const XMLAttributes attributes = xmlAttributes(tag);
  const std::string* value = findAttribute(attributes, name);
  return value ? *value : std::string();
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
  // expat expands a declared entity in an attribute value; the checks below
  // read the values with the predefined references only.
  if (text.find("<!ENTITY") != std::string::npos)
  {
    return "an entity declaration, which VTK's XML files do not have";
  }
  static const char* const names[] = { "NumberOfPoints", "NumberOfVerts", "NumberOfLines", "NumberOfStrips",
    "NumberOfPolys", "NumberOfTuples", "NumberOfComponents" };
  for (size_t at = text.find('<'); at != std::string::npos && at < text.size(); at = text.find('<', at + 1))
  {
    // Comments, CDATA sections and processing instructions may hold any
    // character but their end marker, quotes and '<' included: skip them.
    static const char* const skipped[][2] = { { "<!--", "-->" }, { "<![CDATA[", "]]>" }, { "<?", "?>" } };
    const auto kind = std::find_if(std::begin(skipped), std::end(skipped),
      [&](const char* const* marks) { return text.compare(at, std::strlen(marks[0]), marks[0]) == 0; });
    if (kind != std::end(skipped))
    {
      at = std::min(text.find((*kind)[1], at + std::strlen((*kind)[0])), text.size());
      continue;
    }
    // Elsewhere in a well-formed file '<' starts a tag, and its value quotes
    // and '>' close: where they do not, expat refuses the file.
    const size_t end = tagEnd(text, at);
    if (end == std::string::npos)
    {
      break;
    }
    const XMLAttributes attributes = xmlAttributes(text.substr(at, end - at));
    for (const char* name : names)
    {
      const std::string* found = findAttribute(attributes, name);
      if (!found)
      {
        continue;
      }
      const std::string& value = *found;
      // VTK reads a count with operator>>: white space, a sign, digits.
      size_t begin = value.find_first_not_of(' ');
      begin = begin != std::string::npos && value[begin] == '+' ? begin + 1 : begin;
      unsigned long long count = 0;
      size_t i = begin;
      for (; i < value.size() && i < begin + 21 && value[i] >= '0' && value[i] <= '9'; ++i)
      {
        count = count * 10 + static_cast<unsigned long long>(value[i] - '0');
      }
      if (begin != std::string::npos && (i - begin > 20 || count > limit))
      {
        return std::string(name) + "=" + value.substr(begin, std::min<size_t>(i - begin, 20)) +
          " is more than a file of " + std::to_string(size) + " bytes can hold";
      }
    }
  }

  // Compressed arrays start with a header: the number of blocks, the block
  // size, the last block's size, then each block's compressed size. VTK
  // allocates what the first two say: both must fit the file.
  const size_t fileTag = text.find("<VTKFile");
  const std::string vtkFile = fileTag == std::string::npos ? std::string() : text.substr(fileTag, tagEnd(text, fileTag) - fileTag);
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
    // VTK starts inline data after the first '>' from the element's start,
    // even one inside a quoted value; the attributes end at the tag's end.
    const size_t close = text.find('>', at);
    const size_t end = tagEnd(text, at);
    if (close == std::string::npos || end == std::string::npos)
    {
      break;
    }
    const XMLAttributes attributes = xmlAttributes(text.substr(at, end - at));
    const std::string* formatValue = findAttribute(attributes, "format");
    const std::string* nameValue = findAttribute(attributes, "Name");
    const std::string format = formatValue ? *formatValue : std::string();
    const std::string name = shadelab::printableText(nameValue ? *nameValue : std::string());
    const std::string* offsetText = findAttribute(attributes, "offset");
    const bool hasOffset = offsetText != nullptr;
    // The first @p n bytes of the array's compression header ("" if its data
    // does not start within the file).
    bool located = false; // the array's data starts within the file
    size_t dataAt = 0;
    // VTK reads an array with an offset from the appended data, whatever its
    // format says, and one without from the element: binary only when its
    // format says so.
    const bool inlineBinary = !hasOffset && format == "binary";
    if (inlineBinary)
    {
      // vtkXMLDataParser starts inline data at its first non-space character.
      located = true;
      dataAt = text.find_first_not_of(" \t\r\n", close + 1);
      dataAt = dataAt == std::string::npos ? text.size() : dataAt;
    }
    else if (hasOffset)
    {
      long long offset = 0;
      std::istringstream(*offsetText) >> offset; // as vtkXMLDataElement reads it
      if (offset < 0)
      {
        return "DataArray \"" + name + "\": its offset " + std::to_string(offset) + " is negative";
      }
      if (appendedStart != std::string::npos && static_cast<unsigned long long>(offset) < bytes.size() - appendedStart)
      {
        located = true;
        dataAt = appendedStart + static_cast<size_t>(offset);
      }
    }
    const bool base64Encoded = inlineBinary || (hasOffset && appendedBase64);
    auto headerBytes = [&](size_t n) -> std::string {
      if (!located)
      {
        return std::string();
      }
      return base64Encoded ? base64(inlineBinary ? text : bytes, dataAt, n) : bytes.substr(dataAt, n);
    };
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
