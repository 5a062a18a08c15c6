#include "slFileExtension.h"

#include <algorithm>
#include <cctype>

std::string slLowerExtension(const char* fileName)
{
  const std::string name = fileName ? fileName : "";
  const size_t dot = name.find_last_of('.');
  const size_t slash = name.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return std::string();
  }
  std::string ext = name.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

bool slExtensionInList(const std::string& extension, const char* list)
{
  return !extension.empty() && (" " + std::string(list) + " ").find(" " + extension + " ") != std::string::npos;
}

std::string slFormatProblem(const char* fileName, const char* kind, const char* list)
{
  const std::string ext = slLowerExtension(fileName);
  if (slExtensionInList(ext, list))
  {
    return std::string();
  }
  const std::string supported = std::string(" (supported: ") + list + ")";
  if (ext.empty())
  {
    return std::string("no file extension to tell the ") + kind + " format" + supported;
  }
  return std::string("unsupported ") + kind + " format \"" + ext + "\"" + supported;
}
