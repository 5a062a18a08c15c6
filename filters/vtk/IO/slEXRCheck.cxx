// OpenEXR headers: a sequence of attributes (name, type name, 32-bit size,
// value), each header ended by an empty name; a multi-part file has several
// headers and an empty one after the last. OpenEXR sizes a string
// attribute's buffer from its size field before reading it.
#include "slImageFileCheck.h"

#include "shadelab/PrintableText.h"

#include <cstdint>
#include <fstream>
#include <algorithm>

namespace
{
constexpr unsigned char kMagic[4] = { 0x76, 0x2f, 0x31, 0x01 };
/// OpenEXR reads names of up to 255 bytes whether or not the file's
/// long-names flag is set.
constexpr size_t kLongestName = 255;
constexpr std::uint32_t kMultiPartFlag = 0x1000;

/// The file, walked from the front without reading attribute values.
struct Cursor
{
  std::ifstream& file;
  std::uint64_t size;
  std::uint64_t at;

  std::uint64_t Left() const { return size - at; }

  /// The NUL-terminated text at the cursor (moving past it), or false when no
  /// NUL comes within @p longest + 1 bytes or before the end of the file.
  bool Text(size_t longest, std::string& text)
  {
    text.clear();
    file.seekg(static_cast<std::streamoff>(at));
    for (char c; text.size() <= longest && at < size && file.get(c);)
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

  /// The little-endian 32-bit integer at the cursor (moving past it).
  bool Int32(std::int32_t& value)
  {
    unsigned char b[4];
    file.seekg(static_cast<std::streamoff>(at));
    if (Left() < 4 || !file.read(reinterpret_cast<char*>(b), 4))
    {
      return false;
    }
    at += 4;
    value = static_cast<std::int32_t>(b[0] | (b[1] << 8) | (b[2] << 16) | (std::uint32_t(b[3]) << 24));
    return true;
  }
};
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
  for (bool headerEmpty = false; !headerEmpty;)
  {
    headerEmpty = true;
    for (;;)
    {
      const size_t start = cursor.at;
      std::string name, type;
      if (!cursor.Text(kLongestName, name))
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
      if (!cursor.Text(kLongestName, type) || !cursor.Int32(valueSize))
      {
        return quoted + " at byte " + std::to_string(start) + ": its type and size do not fit in the file";
      }
      if (valueSize < 0 || static_cast<std::uint64_t>(valueSize) > cursor.Left())
      {
        return quoted + " (" + shadelab::printableText(type) + ") at byte " + std::to_string(start) + " declares " +
          std::to_string(valueSize) + " bytes; " + slBytesRemain(cursor.Left());
      }
      cursor.at += static_cast<std::uint64_t>(valueSize);
    }
    if (!multiPart)
    {
      break;
    }
  }
  return "";
}
