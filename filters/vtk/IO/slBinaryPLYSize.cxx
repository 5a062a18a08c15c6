#include "slBinaryPLYSize.h"

#include <map>
#include <sstream>

namespace
{
/// Bytes of a PLY scalar type; 0 if unknown.
int typeSize(const std::string& type)
{
  static const std::map<std::string, int> sizes{ { "char", 1 }, { "uchar", 1 }, { "int8", 1 }, { "uint8", 1 },
    { "short", 2 }, { "ushort", 2 }, { "int16", 2 }, { "uint16", 2 }, { "int", 4 }, { "uint", 4 }, { "int32", 4 },
    { "uint32", 4 }, { "float", 4 }, { "float32", 4 }, { "double", 8 }, { "float64", 8 } };
  const auto found = sizes.find(type);
  return found == sizes.end() ? 0 : found->second;
}
} // namespace

std::int64_t slBinaryPLYSize(const std::string& bytes, std::int64_t listEntries)
{
  const std::string endHeader = "end_header\n";
  const size_t end = bytes.find(endHeader);
  if (bytes.compare(0, 4, "ply\n") != 0 || end == std::string::npos)
  {
    return -1;
  }
  std::istringstream header(bytes.substr(0, end));
  std::int64_t size = static_cast<std::int64_t>(end + endHeader.size());
  std::int64_t elementCount = 0;
  int lists = 0;
  std::string line;
  while (std::getline(header, line))
  {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format")
    {
      std::string format;
      words >> format;
      if (format != "binary_little_endian" && format != "binary_big_endian")
      {
        return -1;
      }
    }
    else if (keyword == "element")
    {
      std::string name;
      words >> name >> elementCount;
    }
    else if (keyword == "property")
    {
      std::string type;
      words >> type;
      if (type == "list")
      {
        std::string countType, entryType;
        words >> countType >> entryType;
        if (typeSize(countType) == 0 || typeSize(entryType) == 0 || ++lists > 1)
        {
          return -1;
        }
        size += elementCount * typeSize(countType) + listEntries * typeSize(entryType);
      }
      else if (typeSize(type) == 0)
      {
        return -1;
      }
      else
      {
        size += elementCount * typeSize(type);
      }
    }
  }
  return size;
}
