#include "shadelab/InputFile.h"

#include <filesystem>

namespace shadelab
{

std::string inputFileProblem(const std::string& path, const std::string& what)
{
  std::error_code error;
  // status() follows symbolic links: a link to /dev/zero is a device.
  const std::filesystem::file_type type = std::filesystem::status(path, error).type();
  if (error || type == std::filesystem::file_type::regular || type == std::filesystem::file_type::not_found)
  {
    return std::string();
  }
  if (type == std::filesystem::file_type::directory)
  {
    return "is a directory, not " + what;
  }
  return "is not a regular file (a device, pipe or socket)";
}

} // namespace shadelab
