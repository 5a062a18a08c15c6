#include "shadelab/InputFile.h"

#include <cerrno>
#include <filesystem>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

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

std::string openFailureReason(const std::string& path)
{
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd >= 0)
  {
    ::close(fd);
    return "it could not be opened";
  }
  return std::generic_category().message(errno);
}

} // namespace shadelab
