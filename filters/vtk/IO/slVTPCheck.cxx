// VTP: the counts and compression headers VTK's XML reader allocates for
// must fit what the file can hold. VTK 9.1 allocates a NumberOfPoints, a
// compressed array's block count and each block's size as the file states
// them, before reading any data; it reads a negative count as it is, and
// each array's data from where its header says, as far as the file goes.
#include "slErrorCapture.h"
#include "slMeshFileCheck.h"
#include "slXMLStartTags.h"

#include "shadelab/PrintableText.h"

#include <vtkBase64InputStream.h>
#include <vtkLZ4DataCompressor.h>
#include <vtkLZMADataCompressor.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkZLibDataCompressor.h>

#include <algorithm>
#include <cctype>
#include <limits>
#include <new>
#include <numeric>
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

/// A count attribute as VTK reads it with operator>>: white space, a sign, digits.
struct Count
{
  bool read = false;            ///< digits follow the sign: VTK takes the value
  bool negative = false;        ///< a '-' before digits other than all zeros
  unsigned long long value = 0; ///< the magnitude, saturated (past 20 digits too)
  std::string text;             ///< as messages quote it: '-' if negative, up to 20 digits
};

Count readCount(const std::string& value)
{
  Count count;
  size_t i = value.find_first_not_of(' ');
  if (i == std::string::npos)
  {
    return count;
  }
  const bool minus = value[i] == '-';
  i += minus || value[i] == '+' ? 1 : 0;
  const size_t begin = i;
  const unsigned long long most = std::numeric_limits<unsigned long long>::max();
  for (; i < value.size() && i < begin + 21 && value[i] >= '0' && value[i] <= '9'; ++i)
  {
    const unsigned digit = static_cast<unsigned>(value[i] - '0');
    count.value = count.value > (most - digit) / 10 ? most : count.value * 10 + digit;
  }
  count.read = i > begin;
  count.value = i - begin > 20 ? most : count.value;
  count.negative = minus && count.value != 0;
  count.text = (count.negative ? "-" : "") + value.substr(begin, std::min<size_t>(i - begin, 20));
  return count;
}

/// The first count attribute of @p tags that is negative (VTK reads it as
/// it is, and reads as many values before the array's start: a crash) or
/// larger than a file of @p size bytes can hold, as "Name=value is ...", or
/// "". An array's NumberOfComponents is checked with the array.
std::string countProblem(const std::vector<slXMLStartTag>& tags, unsigned long long size)
{
  static const char* const names[] = { "NumberOfPoints", "NumberOfVerts", "NumberOfLines", "NumberOfStrips",
    "NumberOfPolys", "NumberOfTuples" };
  for (const slXMLStartTag& tag : tags)
  {
    for (const char* name : names)
    {
      const std::string* found = slFindXMLAttribute(tag.attributes, name);
      const Count count = found ? readCount(*found) : Count();
      if (count.negative)
      {
        return std::string(name) + "=" + count.text + " is negative";
      }
      if (count.value > countLimit(size))
      {
        return std::string(name) + "=" + count.text + " is more than a file of " + std::to_string(size) +
          " bytes can hold";
      }
    }
  }
  return std::string();
}

/// The DataArray types ShadeLab reads: the numeric ones VTK's XML writer
/// writes. VTK's reader also takes "String" and "Bit", which no mesh array
/// of ShadeLab's holds (and a String array's appended data made it crash).
const char* const numericTypes[] = { "Int8", "UInt8", "Int16", "UInt16", "Int32", "UInt32", "Int64", "UInt64",
  "Float32", "Float64" };

/// The problem with the type or NumberOfComponents of the DataArray @p tag,
/// named @p name, in a file of @p size bytes, or "".
std::string arrayAttributeProblem(const slXMLStartTag& tag, const std::string& name, unsigned long long size)
{
  const std::string* type = slFindXMLAttribute(tag.attributes, "type");
  if (!type || std::find(std::begin(numericTypes), std::end(numericTypes), *type) == std::end(numericTypes))
  {
    const std::string types = std::accumulate(std::begin(numericTypes) + 1, std::end(numericTypes),
      std::string(numericTypes[0]), [](const std::string& list, const char* t) { return list + ", " + t; });
    return "DataArray \"" + name + "\": " +
      (type ? "type \"" + shadelab::printableText(*type) + "\" is not one of the numeric types VTK writes (" + types + ")"
            : "it has no type (one of the numeric types VTK writes: " + types + ")");
  }
  // VTK's arrays size a tuple buffer by the component count: a negative one
  // throws, and 0 leaves it empty while the array keeps 1 component.
  const std::string* components = slFindXMLAttribute(tag.attributes, "NumberOfComponents");
  const Count count = components ? readCount(*components) : Count();
  if (count.read && (count.negative || count.value == 0))
  {
    return "DataArray \"" + name + "\": NumberOfComponents=" + count.text + " is less than 1";
  }
  if (count.value > countLimit(size))
  {
    return "DataArray \"" + name + "\": NumberOfComponents=" + count.text + " is more than a file of " +
      std::to_string(size) + " bytes can hold";
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
  count = std::min(count, (end - begin) / 4 * 3); // what the text can hold, not what a header claims
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

/// What a file's arrays share: the file, its header words, its compressor
/// and where its appended data starts.
struct VTPFile
{
  const std::string& bytes;
  size_t markupEnd;     ///< where the markup ends: the AppendedData tag, or the file's end
  size_t appendedStart; ///< the appended data's first byte after "_", or npos
  bool appendedBase64;
  int wordSize;
  bool little;
  const std::string* compressor; ///< the VTKFile element's compressor attribute, or null if none or empty
};

/// Where the data of the DataArray @p tag starts in @p file, and whether it
/// is base64: (npos, false) when it does not start within the file, or for
/// an array that is neither appended nor inline binary. @p offset: the
/// array's offset attribute, not negative, or null when it has none.
std::pair<size_t, bool> arrayDataStart(const VTPFile& file, const slXMLStartTag& tag, const long long* offset)
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

/// The DataArray's name, as messages quote it.
std::string arrayName(const slXMLStartTag& tag)
{
  const std::string* name = slFindXMLAttribute(tag.attributes, "Name");
  return shadelab::printableText(name ? *name : std::string());
}

/// Where a binary array's data follows its header, and what the header
/// says of it: what reading or uncompressing the data needs.
struct ArrayData
{
  size_t at = std::string::npos; ///< its first byte (or base64 character) after the header; npos: not binary
  size_t end = 0;                ///< where the file's text for it ends
  bool base64 = false;
  unsigned long long blockSize = 0;                ///< compressed: each block's uncompressed size...
  unsigned long long lastBlockSize = 0;            ///< ...but the last one's, when not 0
  std::vector<unsigned long long> compressedSizes; ///< compressed: each block's compressed size
};

/// The problem with the header of the binary DataArray @p tag of @p file,
/// or with where its data would end, or "". @p data: where the data is, when
/// there is no problem.
std::string arrayHeaderProblem(const VTPFile& file, const slXMLStartTag& tag, ArrayData& data)
{
  const std::string name = arrayName(tag);
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
  if ((dataAt == std::string::npos && !offsetText) || (offsetText && file.appendedStart == std::string::npos))
  {
    return std::string(); // not binary; or appended without appended data, which VTK says
  }
  const bool base64Encoded = start.second;
  const size_t dataEnd = offsetText ? file.bytes.size() : file.markupEnd;
  // VTK encodes a header and the data after it each on its own.
  auto encodedLength = [&](size_t n) { return base64Encoded ? (n + 2) / 3 * 4 : n; };
  // The first @p n bytes of the array's header ("" if its data does not
  // start within the file).
  auto headerBytes = [&](size_t n) -> std::string {
    if (dataAt == std::string::npos)
    {
      return std::string();
    }
    return base64Encoded ? base64(file.bytes, dataAt, dataEnd, n) : file.bytes.substr(dataAt, n);
  };
  // The problem when the file holds only @p header of the @p n bytes of header.
  const std::string kind = file.compressor ? "compression header" : "header";
  auto shortHeader = [&](size_t n, const std::string& header) -> std::string {
    if (base64Encoded && dataAt != std::string::npos)
    {
      // vtkBase64InputStream decodes what it is given, padding and bytes
      // outside the alphabet included, and would take a header from them.
      return "DataArray \"" + name + "\": its " + kind + " is not " + std::to_string(n) + " bytes of base64";
    }
    return "DataArray \"" + name + "\": the file ends within its " + kind + " (" + std::to_string(header.size()) +
      " of " + std::to_string(n) + " bytes)";
  };
  // VTK reads each array's data as far as the file goes, and reports a short
  // read, if at all, for a later array: its data must be in the file.
  auto shortData = [&](size_t headerSize, unsigned long long needed) -> std::string {
    data.at = dataAt + encodedLength(headerSize);
    data.end = dataEnd;
    data.base64 = base64Encoded;
    const size_t text = data.at < dataEnd ? dataEnd - data.at : 0;
    const unsigned long long held = base64Encoded ? text / 4 * 3 : text;
    if (needed <= held)
    {
      return std::string();
    }
    return "DataArray \"" + name + "\": its " + kind + " declares " + std::to_string(needed) + " bytes" +
      (file.compressor ? " of compressed data" : " of data") + ", the file holds " + std::to_string(held) +
      " after it";
  };
  const unsigned long long size = file.bytes.size();
  const size_t wordSize = static_cast<size_t>(file.wordSize);
  if (!file.compressor)
  {
    // Uncompressed: the number of bytes of data, then the data.
    const std::string header = headerBytes(wordSize);
    return header.size() < wordSize ? shortHeader(wordSize, header)
                                    : shortData(wordSize, word(header, 0, file.wordSize, file.little));
  }

  // Compressed arrays start with a header: the number of blocks, the block
  // size, the last block's size, then each block's compressed size. VTK
  // allocates what the first two say: both must fit the file.
  const std::string header = headerBytes(3 * wordSize);
  if (header.size() < 3 * wordSize)
  {
    return shortHeader(3 * wordSize, header);
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
    return shortHeader(fullSize, full);
  }
  data.compressedSizes.clear();
  for (unsigned long long b = 0; b < blocks; ++b)
  {
    const unsigned long long compressed = word(full, static_cast<size_t>(3 + b) * wordSize, file.wordSize, file.little);
    if (compressed > size)
    {
      return "DataArray \"" + name + "\": its compression header gives block " + std::to_string(b) + " " +
        std::to_string(compressed) + " compressed bytes, more than the file's " + std::to_string(size);
    }
    data.compressedSizes.push_back(compressed);
  }
  data.blockSize = blockSize;
  data.lastBlockSize = lastBlockSize;
  // At most size / wordSize blocks of at most size bytes each: no overflow.
  return shortData(
    fullSize, std::accumulate(data.compressedSizes.begin(), data.compressedSizes.end(), 0ULL));
}

/// The attribute @p name of the first tag named @p element, or null.
const std::string* elementAttribute(
  const std::vector<slXMLStartTag>& tags, const std::string& element, const std::string& name)
{
  const auto tag =
    std::find_if(tags.begin(), tags.end(), [&](const slXMLStartTag& t) { return t.name == element; });
  return tag == tags.end() ? nullptr : slFindXMLAttribute(tag->attributes, name);
}

bool attributeIs(const std::vector<slXMLStartTag>& tags, const std::string& element, const std::string& name,
  const std::string& value)
{
  const std::string* found = elementAttribute(tags, element, name);
  return found && *found == value;
}

/// The problem with where the appended data of @p tags (read from
/// file.bytes) starts, or ""; @p file then holds the file's layout.
std::string fileLayoutProblem(const std::vector<slXMLStartTag>& tags, VTPFile& file)
{
  const bool hasAppended = !tags.empty() && tags.back().name == "AppendedData";
  const std::string& bytes = file.bytes;
  file.markupEnd = hasAppended ? tags.back().begin : bytes.size();
  file.appendedStart = std::string::npos;
  file.appendedBase64 = attributeIs(tags, "AppendedData", "encoding", "base64");
  file.wordSize = attributeIs(tags, "VTKFile", "header_type", "UInt64") ? 8 : 4;
  file.little = !attributeIs(tags, "VTKFile", "byte_order", "BigEndian");
  const std::string* compressor = elementAttribute(tags, "VTKFile", "compressor");
  file.compressor = compressor && !compressor->empty() ? compressor : nullptr;
  if (!hasAppended)
  {
    return std::string();
  }
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
  return std::string();
}

/// The compressor VTK's XML reader makes for @p name (vtkXMLReader::SetupCompressor), or null.
vtkSmartPointer<vtkDataCompressor> makeCompressor(const std::string& name)
{
  if (name == "vtkZLibDataCompressor")
  {
    return vtkSmartPointer<vtkZLibDataCompressor>::New();
  }
  if (name == "vtkLZ4DataCompressor")
  {
    return vtkSmartPointer<vtkLZ4DataCompressor>::New();
  }
  if (name == "vtkLZMADataCompressor")
  {
    return vtkSmartPointer<vtkLZMADataCompressor>::New();
  }
  return nullptr;
}
} // namespace

std::string slVTPProblem(const std::string& fileName)
{
  const std::string bytes = slReadWholeFile(fileName);
  const std::vector<slXMLStartTag> tags = slReadXMLStartTags(bytes);
  VTPFile file{ bytes, 0, 0, false, 4, true, nullptr };
  const std::string layout = fileLayoutProblem(tags, file);
  // expat expands a declared entity in an attribute value; the tags are read
  // with the predefined references only.
  const std::string entity = "<!ENTITY";
  const auto markupEndAt = bytes.begin() + static_cast<std::ptrdiff_t>(file.markupEnd);
  if (std::search(bytes.begin(), markupEndAt, entity.begin(), entity.end()) != markupEndAt)
  {
    return "an entity declaration, which VTK's XML files do not have";
  }
  const std::string counts = countProblem(tags, bytes.size());
  if (!counts.empty() || !layout.empty())
  {
    return !counts.empty() ? counts : layout;
  }
  for (const slXMLStartTag& tag : tags)
  {
    if (tag.name != "DataArray")
    {
      continue;
    }
    ArrayData data;
    std::string problem = arrayAttributeProblem(tag, arrayName(tag), bytes.size());
    problem = problem.empty() ? arrayHeaderProblem(file, tag, data) : problem;
    if (!problem.empty())
    {
      return problem;
    }
  }
  return std::string();
}

std::string slVTPDataProblem(const std::string& fileName)
{
  const std::string bytes = slReadWholeFile(fileName);
  const std::vector<slXMLStartTag> tags = slReadXMLStartTags(bytes);
  VTPFile file{ bytes, 0, 0, false, 4, true, nullptr };
  vtkSmartPointer<vtkDataCompressor> compressor;
  if (!fileLayoutProblem(tags, file).empty() || !file.compressor || !(compressor = makeCompressor(*file.compressor)))
  {
    return std::string(); // VTK's own message says what it could not read
  }
  // The compressor's own errors ("Zlib error while uncompressing data.") are
  // what this replaces: kept from the output window.
  vtkNew<slErrorCapture> quiet;
  quiet->Watch(compressor);
  try
  {
    std::vector<unsigned char> block;
    for (const slXMLStartTag& tag : tags)
    {
      ArrayData data;
      if (tag.name != "DataArray" || !arrayHeaderProblem(file, tag, data).empty() || data.at == std::string::npos)
      {
        continue;
      }
      const size_t total =
        std::accumulate(data.compressedSizes.begin(), data.compressedSizes.end(), size_t(0));
      const std::string compressed =
        data.base64 ? base64(bytes, data.at, data.end, total) : bytes.substr(data.at, total);
      size_t from = 0;
      for (size_t b = 0; b < data.compressedSizes.size() && from <= compressed.size(); ++b)
      {
        // Every block holds the block size but a partial last one (vtkXMLDataParser::FindBlockSize).
        const bool partial = b + 1 == data.compressedSizes.size() && data.lastBlockSize != 0;
        block.resize(static_cast<size_t>(partial ? data.lastBlockSize : data.blockSize));
        const size_t length = std::min<size_t>(data.compressedSizes[b], compressed.size() - from);
        const auto in = reinterpret_cast<const unsigned char*>(compressed.data() + from);
        if (compressor->Uncompress(in, length, block.data(), block.size()) != block.size())
        {
          return "DataArray \"" + arrayName(tag) + "\": its block " + std::to_string(b) + " of " +
            std::to_string(data.compressedSizes.size()) + " does not uncompress with " + *file.compressor +
            ", the file's compressor";
        }
        from += length;
      }
    }
  }
  catch (const std::bad_alloc&)
  {
    // A block size too large to hold here: VTK's message stands.
  }
  return std::string();
}
