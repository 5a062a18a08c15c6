#include "shadelab/PrintableText.h"

#include <cstdio>

namespace shadelab
{

std::string printableText(const std::string& bytes, size_t maxBytes)
{
  std::string out;
  const size_t n = bytes.size() < maxBytes ? bytes.size() : maxBytes;
  for (size_t i = 0; i < n; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(bytes[i]);
    if (c >= 0x20 && c < 0x7f && c != '\\')
    {
      out += static_cast<char>(c);
    }
    else
    {
      char escaped[8];
      std::snprintf(escaped, sizeof(escaped), "\\x%02X", c);
      out += escaped;
    }
  }
  if (n < bytes.size())
  {
    out += "...";
  }
  return out;
}

} // namespace shadelab
