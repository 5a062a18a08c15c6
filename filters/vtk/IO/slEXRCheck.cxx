// OpenEXR headers: a sequence of attributes (name, type name, 32-bit size,
// value), each header ended by an empty name; a multi-part file has several
// headers and an empty one after the last. Then comes the offset table:
// one 64-bit offset per chunk of every part.
//
// OpenEXR sizes a string attribute's buffer from its size field, a string
// vector's strings from their own length fields, a preview's pixels from
// its width and height, the offset table from the data window, and a
// tile's buffer from the tile size, before reading any of them. It also
// reads the value of an attribute of a known type by the type's layout, not
// by the size field: a size that disagrees with the layout makes OpenEXR
// read the rest of the header elsewhere than a walk by size fields would.
// So the walk below checks every value against its type's layout, and
// every length against what remains.
#include "slImageFileCheck.h"

#include "shadelab/PrintableText.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <map>
#include <vector>

namespace
{
constexpr unsigned char kMagic[4] = { 0x76, 0x2f, 0x31, 0x01 };
/// OpenEXR reads names of up to 255 bytes whether or not the file's
/// long-names flag is set.
constexpr size_t kLongestName = 255;
constexpr std::uint32_t kMultiPartFlag = 0x1000;

/// The value size of every fixed-size attribute type OpenEXR knows.
const std::map<std::string, std::int32_t>& fixedSizes()
{
  static const std::map<std::string, std::int32_t> sizes{ { "box2i", 16 }, { "box2f", 16 },
    { "chromaticities", 32 }, { "compression", 1 }, { "deepImageState", 1 }, { "double", 8 }, { "envmap", 1 },
    { "float", 4 }, { "int", 4 }, { "keycode", 28 }, { "lineOrder", 1 }, { "m33f", 36 }, { "m33d", 72 },
    { "m44f", 64 }, { "m44d", 128 }, { "rational", 8 }, { "tiledesc", 9 }, { "timecode", 8 }, { "v2i", 8 },
    { "v2f", 8 }, { "v2d", 16 }, { "v3i", 12 }, { "v3f", 12 }, { "v3d", 24 } };
  return sizes;
}

/// Scan lines per chunk of each compression (OpenEXR's numbering).
std::int64_t linesPerChunk(int compression)
{
  switch (compression)
  {
    case 3: // ZIP
    case 5: // PXR24
      return 16;
    case 4: // PIZ
    case 6: // B44
    case 7: // B44A
    case 8: // DWAA
      return 32;
    case 9: // DWAB
      return 256;
    default: // NONE, RLE, ZIPS and unknown ones: the most chunks
      return 1;
  }
}

std::int32_t int32At(const unsigned char* b)
{
  return static_cast<std::int32_t>(b[0] | (b[1] << 8) | (b[2] << 16) | (std::uint32_t(b[3]) << 24));
}

/// The file, walked from the front; values are read only where OpenEXR
/// would size something from them.
struct Cursor
{
  std::ifstream& file;
  std::uint64_t size;
  std::uint64_t at;

  std::uint64_t Left() const { return size - at; }

  /// The NUL-terminated text at the cursor (moving past it), or false when no
  /// NUL comes within @p longest + 1 bytes or before @p end.
  bool Text(size_t longest, std::string& text, std::uint64_t end)
  {
    text.clear();
    file.seekg(static_cast<std::streamoff>(at));
    for (char c; text.size() <= longest && at < end && file.get(c);)
    {
      ++at;
      if (c == '\0')
      {
        return true;
      }
      text += c;
    }
    return false;
  }

  /// @p count bytes at the cursor (moving past them), or false when fewer remain.
  bool Bytes(std::uint64_t count, std::vector<unsigned char>& bytes)
  {
    if (Left() < count)
    {
      return false;
    }
    bytes.resize(count);
    file.seekg(static_cast<std::streamoff>(at));
    if (count > 0 && !file.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(count)))
    {
      return false;
    }
    at += count;
    return true;
  }

  /// The little-endian 32-bit integer at the cursor (moving past it).
  bool Int32(std::int32_t& value)
  {
    std::vector<unsigned char> b;
    if (!Bytes(4, b))
    {
      return false;
    }
    value = int32At(b.data());
    return true;
  }
};

/// What one header says about the size of its part's offset table.
struct Part
{
  bool haveWindow = false;
  std::int64_t width = 0, height = 0;
  int compression = 0;
  bool tiled = false;
  std::int64_t tileWidth = 1, tileHeight = 1;
  std::int64_t chunkCount = -1; ///< the chunkCount attribute, -1 when absent
  std::int64_t channels = 0;
  std::uint64_t tilesAt = 0; ///< where the tiles attribute starts

  /// The chunks OpenEXR expects: the attribute, else scan-line blocks or
  /// the tiles of the full-resolution level (a lower bound with mipmaps).
  std::int64_t Chunks() const
  {
    if (chunkCount >= 0)
    {
      return chunkCount;
    }
    if (!haveWindow || width <= 0 || height <= 0)
    {
      return 0; // OpenEXR rejects the window itself
    }
    if (tiled)
    {
      // Each factor is below 2^32, their product below 2^64: counted in
      // double, which is exact enough to compare with a file's size.
      return static_cast<std::int64_t>(std::min(4e18,
        static_cast<double>((width + tileWidth - 1) / tileWidth) * ((height + tileHeight - 1) / tileHeight)));
    }
    const std::int64_t lines = linesPerChunk(compression);
    return (height + lines - 1) / lines;
  }
};

/// The problem with a value of type @p type and @p size bytes at the
/// cursor, which is left at its end; notes what @p part needs from it.
std::string valueProblem(Cursor& cursor, const std::string& name, const std::string& type, std::int32_t size,
  Part& part)
{
  const std::uint64_t end = cursor.at + static_cast<std::uint64_t>(size);
  const auto fixed = fixedSizes().find(type);
  std::vector<unsigned char> bytes;
  if (fixed != fixedSizes().end())
  {
    if (size != fixed->second)
    {
      return "its type takes " + std::to_string(fixed->second) + " bytes";
    }
    if (!cursor.Bytes(static_cast<std::uint64_t>(size), bytes))
    {
      return "its value cannot be read";
    }
    if (name == "dataWindow" && type == "box2i")
    {
      part.haveWindow = true;
      part.width = std::int64_t(int32At(&bytes[8])) - int32At(&bytes[0]) + 1;
      part.height = std::int64_t(int32At(&bytes[12])) - int32At(&bytes[4]) + 1;
    }
    else if (name == "compression" && type == "compression")
    {
      part.compression = bytes[0];
    }
    else if (name == "tiles" && type == "tiledesc")
    {
      part.tiled = true;
      part.tileWidth = std::max<std::int64_t>(1, static_cast<std::uint32_t>(int32At(&bytes[0])));
      part.tileHeight = std::max<std::int64_t>(1, static_cast<std::uint32_t>(int32At(&bytes[4])));
    }
    else if (name == "chunkCount" && type == "int")
    {
      part.chunkCount = std::max<std::int64_t>(0, int32At(&bytes[0]));
    }
    return "";
  }
  if (type == "chlist")
  {
    // Channels (name, 16 bytes) up to an empty name: OpenEXR reads them
    // whatever the size says.
    for (std::string channel;;)
    {
      if (!cursor.Text(kLongestName, channel, end))
      {
        return "a channel name that does not end within its size";
      }
      if (channel.empty())
      {
        return cursor.at == end ? "" : "its channel list ends before its size";
      }
      if (end - cursor.at < 16)
      {
        return "channel '" + shadelab::printableText(channel) + "' does not fit in its size";
      }
      cursor.at += 16;
      part.channels += name == "channels";
    }
  }
  if (type == "preview")
  {
    if (size < 8 || !cursor.Bytes(8, bytes))
    {
      return "its size is too small for a preview's width and height";
    }
    const std::uint64_t pixels = std::uint64_t(static_cast<std::uint32_t>(int32At(&bytes[0]))) *
      static_cast<std::uint32_t>(int32At(&bytes[4]));
    if (4 * pixels != static_cast<std::uint64_t>(size) - 8)
    {
      return "its preview of " + std::to_string(pixels) + " pixels needs " + std::to_string(4 * pixels + 8) +
        " bytes";
    }
  }
  if (type == "stringvector")
  {
    for (std::int32_t length = 0; cursor.at < end; cursor.at += static_cast<std::uint64_t>(length))
    {
      const std::uint64_t start = cursor.at;
      if (end - cursor.at < 4 || !cursor.Int32(length) || length < 0 ||
        static_cast<std::uint64_t>(length) > end - cursor.at)
      {
        return "the string at byte " + std::to_string(start) + " does not fit in its size";
      }
    }
  }
  cursor.at = end;
  return "";
}
} // namespace

std::string slEXRProblem(const std::string& fileName)
{
  std::ifstream file(fileName, std::ios::binary);
  unsigned char magic[8] = {};
  if (!file || !file.read(reinterpret_cast<char*>(magic), 8) || !std::equal(kMagic, kMagic + 4, magic))
  {
    return "";
  }
  file.seekg(0, std::ios::end);
  const std::uint64_t size = static_cast<std::uint64_t>(file.tellg());
  const std::uint32_t flags = magic[4] | (magic[5] << 8) | (magic[6] << 16) | (std::uint32_t(magic[7]) << 24);
  const bool multiPart = flags & kMultiPartFlag;

  Cursor cursor{ file, size, 8 };
  std::int64_t chunks = 0;
  for (bool headerEmpty = false; !headerEmpty;)
  {
    headerEmpty = true;
    Part part;
    for (;;)
    {
      const size_t start = cursor.at;
      std::string name, type;
      if (!cursor.Text(kLongestName, name, size))
      {
        return "EXR header at byte " + std::to_string(start) + ": an attribute name that does not end within " +
          std::to_string(kLongestName) + " bytes or before the end of the file";
      }
      if (name.empty())
      {
        break; // the end of this header
      }
      headerEmpty = false;
      const std::string quoted = "EXR attribute '" + shadelab::printableText(name) + "'";
      std::int32_t valueSize = 0;
      if (!cursor.Text(kLongestName, type, size) || !cursor.Int32(valueSize))
      {
        return quoted + " at byte " + std::to_string(start) + ": its type and size do not fit in the file";
      }
      const std::string typed = quoted + " (" + shadelab::printableText(type) + ") at byte " + std::to_string(start);
      if (valueSize < 0 || static_cast<std::uint64_t>(valueSize) > cursor.Left())
      {
        return typed + " declares " + std::to_string(valueSize) + " bytes; " + slBytesRemain(cursor.Left());
      }
      part.tilesAt = name == "tiles" ? start : part.tilesAt;
      const std::string problem = valueProblem(cursor, name, type, valueSize, part);
      if (!problem.empty())
      {
        return typed + " declares " + std::to_string(valueSize) + " bytes, but " + problem;
      }
    }
    // OpenEXR allocates a buffer for a tile of every channel as it opens
    // the file, and OpenImageIO another as it reads.
    const std::string tooLarge = !part.tiled ? "" :
      slTooManyValues("tiles of ", static_cast<double>(part.tileWidth), static_cast<double>(part.tileHeight),
        static_cast<double>(std::max<std::int64_t>(1, part.channels)));
    if (!tooLarge.empty())
    {
      return "EXR attribute 'tiles' (tiledesc) at byte " + std::to_string(part.tilesAt) + " declares " + tooLarge;
    }
    chunks = std::min<std::int64_t>(chunks + (headerEmpty ? 0 : part.Chunks()), std::int64_t(4e18));
    if (!multiPart)
    {
      break;
    }
  }
  if (static_cast<std::uint64_t>(chunks) > cursor.Left() / 8)
  {
    return "EXR offset table at byte " + std::to_string(cursor.at) + " has " + std::to_string(chunks) +
      " chunks of 8 bytes; " + slBytesRemain(cursor.Left());
  }
  return "";
}
