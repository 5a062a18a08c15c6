#include "slImageFileCheck.h"

#include "shadelab/PrintableText.h"

#include <cstdint>
#include <cstring>
#include <fstream>

namespace
{
constexpr unsigned char kSignature[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };
/// A chunk's length is at most 2^31 - 1 (PNG specification, 5.3).
constexpr std::uint64_t kMaximumChunk = 0x7fffffffu;
/// Length, type and CRC around each chunk's data.
constexpr std::uint64_t kChunkFrame = 12;
} // namespace

std::string slPNGProblem(const std::string& fileName)
{
  std::ifstream file(fileName, std::ios::binary | std::ios::ate);
  if (!file)
  {
    return "";
  }
  const std::uint64_t size = static_cast<std::uint64_t>(file.tellg());
  file.seekg(0);
  unsigned char signature[8] = {};
  if (!file.read(reinterpret_cast<char*>(signature), 8) || std::memcmp(signature, kSignature, 8) != 0)
  {
    return "";
  }
  for (std::uint64_t at = 8; at + 8 <= size;)
  {
    unsigned char header[8];
    file.seekg(static_cast<std::streamoff>(at));
    if (!file.read(reinterpret_cast<char*>(header), 8))
    {
      return "";
    }
    const std::uint64_t length = (std::uint64_t(header[0]) << 24) | (std::uint64_t(header[1]) << 16) |
      (std::uint64_t(header[2]) << 8) | std::uint64_t(header[3]);
    const std::string type = shadelab::printableText(std::string(reinterpret_cast<char*>(header) + 4, 4));
    const std::uint64_t left = size - at - 8;
    if (length > kMaximumChunk || length + 4 > left)
    {
      const std::uint64_t remain = left > 4 ? left - 4 : 0; // what its data may take, before the CRC
      return "PNG chunk '" + type + "' at byte " + std::to_string(at) + " declares " + std::to_string(length) +
        " bytes of data; " + slBytesRemain(remain);
    }
    if (std::memcmp(header + 4, "IEND", 4) == 0)
    {
      break;
    }
    at += kChunkFrame + length;
  }
  return "";
}
