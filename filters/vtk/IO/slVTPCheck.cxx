// VTP: the counts and compression headers VTK's XML reader allocates for
// must fit what the file can hold. VTK 9.1 allocates a NumberOfPoints, a
// compressed array's block count and each block's size as the file states
// them, before reading any data.
#include "slMeshFileCheck.h"
#include "slXMLStartTags.h"

#include "shadelab/PrintableText.h"

#include <vtkBase64InputStream.h>
#include <vtkNew.h>

#include <algorithm>
#include <cctype>
#include <sstream>
#include <utility>
#include <vector>

namespace
{
/// Every point and cell takes at least one value in the file, and zlib, the
/// densest compression VTK's XML writer uses, packs at most 1032 bytes into
/// one: a count beyond this is one VTK would allocate for in vain.
unsigned long long countLimit(unsigned long long fileSize)
{
  return 1032 * (fileSize + 1);
}

/// The first count attribute of @p tags larger than a file of @p size bytes
/// can hold, as "Name=value is more than...", or "".
std::string countProblem(const std::vector<slXMLStartTag>& tags, unsigned long long size)
{
  static const char* const names[] = { "NumberOfPoints", "NumberOfVerts", "NumberOfLines", "NumberOfStrips",
    "NumberOfPolys", "NumberOfTuples", "NumberOfComponents" };
  for (const slXMLStartTag& tag : tags)
  {
    for (const char* name : names)
    {
      const std::string* found = slFindXMLAttribute(tag.attributes, name);
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
      if (begin != std::string::npos && (i - begin > 20 || count > countLimit(size)))
      {
        return std::string(name) + "=" + value.substr(begin, std::min<size_t>(i - begin, 20)) +
          " is more than a file of " + std::to_string(size) + " bytes can hold";
      }
    }
  }
  return std::string();
}

/// @p count bytes decoded from the base64 text of @p bytes between @p begin
/// and @p end, as vtkXMLDataParser decodes them (vtkBase64InputStream: four
/// characters at a time, as they are, padding and bytes outside the alphabet
/// included); fewer if the text ends first.
std::string base64(const std::string& bytes, size_t begin, size_t end, size_t count)
{
  if (begin >= end)
  {
    return std::string();
  }
  std::istringstream in(bytes.substr(begin, std::min((count + 2) / 3 * 4, end - begin)));
  vtkNew<vtkBase64InputStream> stream;
  stream->SetStream(&in);
  stream->StartReading();
  std::string out(count, '\0');
  const size_t read = stream->Read(&out[0], count);
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

/// What a compressed file's arrays share: the file, its header words and
/// where its appended data starts.
struct CompressedFile
{
  const std::string& bytes;
  size_t markupEnd;     ///< where the markup ends: the AppendedData tag, or the file's end
  size_t appendedStart; ///< the appended data's first byte after "_", or npos
  bool appendedBase64;
  int wordSize;
  bool little;
};

/// Where the data of the DataArray @p tag starts in @p file, and whether it
/// is base64: (npos, false) when it does not start within the file, or for
/// an array that is neither appended nor inline binary. @p offset: the
/// array's offset attribute, not negative, or null when it has none.
std::pair<size_t, bool> arrayDataStart(const CompressedFile& file, const slXMLStartTag& tag, const long long* offset)
{
  // VTK reads an array with an offset from the appended data, whatever its
  // format says, and one without from the element: binary only when its
  // format says so.
  if (offset)
  {
    const bool within = file.appendedStart != std::string::npos &&
      static_cast<unsigned long long>(*offset) < file.bytes.size() - file.appendedStart;
    return { within ? file.appendedStart + static_cast<size_t>(*offset) : std::string::npos, file.appendedBase64 };
  }
  const std::string* format = slFindXMLAttribute(tag.attributes, "format");
  if (!format || *format != "binary")
  {
    return { std::string::npos, false };
  }
  // VTK starts inline data at the first non-space character after the first
  // '>' from the element's start, even one inside a quoted value.
  const size_t close = file.bytes.find('>', tag.begin);
  const size_t start = file.bytes.find_first_not_of(" \t\r\n", close + 1);
  return { std::min(start, file.markupEnd), true };
}

/// The problem with the compression header of the DataArray @p tag of
/// @p file, or "".
std::string arrayHeaderProblem(const CompressedFile& file, const slXMLStartTag& tag)
{
  const std::string* nameValue = slFindXMLAttribute(tag.attributes, "Name");
  const std::string name = shadelab::printableText(nameValue ? *nameValue : std::string());
  const std::string* offsetText = slFindXMLAttribute(tag.attributes, "offset");
  long long offset = 0;
  if (offsetText)
  {
    std::istringstream(*offsetText) >> offset; // as vtkXMLDataElement reads it
  }
  if (offset < 0)
  {
    return "DataArray \"" + name + "\": its offset " + std::to_string(offset) + " is negative";
  }
  const std::pair<size_t, bool> start = arrayDataStart(file, tag, offsetText ? &offset : nullptr);
  const size_t dataAt = start.first;
  const bool base64Encoded = start.second;
  const size_t dataEnd = offsetText ? file.bytes.size() : file.markupEnd;
  // The first @p n bytes of the array's compression header ("" if its data
  // does not start within the file).
  auto headerBytes = [&](size_t n) -> std::string {
    if (dataAt == std::string::npos)
    {
      return std::string();
    }
    return base64Encoded ? base64(file.bytes, dataAt, dataEnd, n) : file.bytes.substr(dataAt, n);
  };
  const unsigned long long size = file.bytes.size();
  const size_t wordSize = static_cast<size_t>(file.wordSize);
  const std::string header = headerBytes(3 * wordSize);
  if (header.size() < 3 * wordSize)
  {
    if (base64Encoded && (dataAt != std::string::npos || !header.empty()))
    {
      // vtkBase64InputStream decodes what it is given, padding and bytes
      // outside the alphabet included, and would take a header from them.
      return "DataArray \"" + name + "\": its compression header is not " + std::to_string(3 * wordSize) +
        " bytes of base64";
    }
    return std::string(); // VTK finds the data missing and says so
  }
  const unsigned long long blocks = word(header, 0, file.wordSize, file.little);
  const unsigned long long blockSize = word(header, wordSize, file.wordSize, file.little);
  const unsigned long long lastBlockSize = word(header, 2 * wordSize, file.wordSize, file.little);
  if (lastBlockSize > blockSize && blockSize <= countLimit(size))
  {
    // VTK allocates the last block's size as it is; no block is larger than the block size.
    return "DataArray \"" + name + "\": its compression header's last block of " + std::to_string(lastBlockSize) +
      " bytes is larger than its block size of " + std::to_string(blockSize);
  }
  if (blocks == 0 && lastBlockSize != 0)
  {
    // VTK takes the data's size as (blocks - 1) * block size + the last
    // block's: with no blocks that wraps around, and VTK reads block 0 of a
    // list it never allocated.
    return "DataArray \"" + name + "\": its compression header declares no blocks but a last block of " +
      std::to_string(lastBlockSize) + " bytes";
  }
  if (blocks > size / wordSize || blockSize > countLimit(size))
  {
    return "DataArray \"" + name + "\": its compression header declares " + std::to_string(blocks) +
      " blocks of " + std::to_string(blockSize) + " bytes, more than a file of " + std::to_string(size) +
      " bytes can hold";
  }
  // Then each block's compressed size, which VTK allocates to read it.
  const size_t fullSize = static_cast<size_t>(3 + blocks) * wordSize;
  const std::string full = headerBytes(fullSize);
  if (full.size() < fullSize)
  {
    if (base64Encoded)
    {
      return "DataArray \"" + name + "\": its compression header's " + std::to_string(blocks) +
        " block sizes are not " + std::to_string(fullSize) + " bytes of base64";
    }
    return std::string(); // VTK finds the header cut short and says so
  }
  for (unsigned long long b = 0; b < blocks; ++b)
  {
    const unsigned long long compressed = word(full, static_cast<size_t>(3 + b) * wordSize, file.wordSize, file.little);
    if (compressed > size)
    {
      return "DataArray \"" + name + "\": its compression header gives block " + std::to_string(b) + " " +
        std::to_string(compressed) + " compressed bytes, more than the file's " + std::to_string(size);
    }
  }
  return std::string();
}

/// The attribute @p name of the first tag named @p element, or "".
std::string elementAttribute(
  const std::vector<slXMLStartTag>& tags, const std::string& element, const std::string& name)
{
  const auto tag =
    std::find_if(tags.begin(), tags.end(), [&](const slXMLStartTag& t) { return t.name == element; });
  const std::string* value = tag == tags.end() ? nullptr : slFindXMLAttribute(tag->attributes, name);
  return value ? *value : std::string();
}
} // namespace

std::string slVTPProblem(const std::string& fileName)
{
  const std::string bytes = slReadWholeFile(fileName);
  const std::vector<slXMLStartTag> tags = slReadXMLStartTags(bytes);
  const bool hasAppended = !tags.empty() && tags.back().name == "AppendedData";
  const size_t markupEnd = hasAppended ? tags.back().begin : bytes.size();
  // expat expands a declared entity in an attribute value; the tags are read
  // with the predefined references only.
  const std::string entity = "<!ENTITY";
  const auto markupEndAt = bytes.begin() + static_cast<std::ptrdiff_t>(markupEnd);
  if (std::search(bytes.begin(), markupEndAt, entity.begin(), entity.end()) != markupEndAt)
  {
    return "an entity declaration, which VTK's XML files do not have";
  }
  const std::string counts = countProblem(tags, bytes.size());
  if (!counts.empty() || elementAttribute(tags, "VTKFile", "compressor").empty())
  {
    return counts;
  }

  // Compressed arrays start with a header: the number of blocks, the block
  // size, the last block's size, then each block's compressed size. VTK
  // allocates what the first two say: both must fit the file.
  CompressedFile file{ bytes, markupEnd, std::string::npos, false,
    elementAttribute(tags, "VTKFile", "header_type") == "UInt64" ? 8 : 4,
    elementAttribute(tags, "VTKFile", "byte_order") != "BigEndian" };
  if (hasAppended)
  {
    // Appended data starts after "_"; offsets count its bytes, or its
    // characters when it is base64 (each array's header encoded on its own).
    // vtkXMLDataParser looks for "_" after the first '>' from the element's
    // start, even one inside a quoted value.
    size_t underscore = bytes.find('>', tags.back().begin) + 1;
    while (underscore < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[underscore])))
    {
      ++underscore;
    }
    if (underscore >= bytes.size() || bytes[underscore] != '_')
    {
      // VTK's writers put "_" first; vtkXMLDataParser takes the data from
      // the first character after the tag's white space, "_" or not.
      return "the AppendedData element's data does not start with \"_\"";
    }
    file.appendedStart = underscore + 1;
    file.appendedBase64 = elementAttribute(tags, "AppendedData", "encoding") == "base64";
  }
  for (const slXMLStartTag& tag : tags)
  {
    const std::string problem = tag.name == "DataArray" ? arrayHeaderProblem(file, tag) : std::string();
    if (!problem.empty())
    {
      return problem;
    }
  }
  return std::string();
}
