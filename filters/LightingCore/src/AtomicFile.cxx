#include "shadelab/AtomicFile.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sys/stat.h>
#include <stdexcept>
#include <unistd.h>
#include <vector>

namespace shadelab
{

AtomicOutput::AtomicOutput(std::string target)
  : Target(std::move(target))
{
  const size_t slash = this->Target.find_last_of('/');
  const std::string folder = slash == std::string::npos ? std::string() : this->Target.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? this->Target : this->Target.substr(slash + 1);
  const size_t dot = name.find_last_of('.');
  const std::string extension = dot == std::string::npos || dot == 0 ? std::string() : name.substr(dot);
  const std::string stem = name.substr(0, name.size() - extension.size());

  std::string pattern = folder + "." + stem + ".partial-XXXXXX" + extension;
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  const int fd = mkstemps(buffer.data(), static_cast<int>(extension.size()));
  if (fd < 0)
  {
    throw std::runtime_error(this->Target + ": cannot create output file: " + std::strerror(errno));
  }
  // mkstemps creates the file 0600; give it the mode a plain open() would
  // (0666 less the umask), or the mode of the file it will replace.
  struct stat existing;
  mode_t mode;
  if (::stat(this->Target.c_str(), &existing) == 0)
  {
    mode = existing.st_mode & 07777;
  }
  else
  {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  ::fchmod(fd, mode);
  ::close(fd);
  this->Temporary = buffer.data();
}

AtomicOutput::~AtomicOutput()
{
  if (!this->Committed)
  {
    std::remove(this->Temporary.c_str());
  }
}

void AtomicOutput::commit()
{
  if (std::rename(this->Temporary.c_str(), this->Target.c_str()) != 0)
  {
    throw std::runtime_error(this->Target + ": cannot write output file: " + std::strerror(errno));
  }
  this->Committed = true;
}

void writeFileAtomically(const std::string& path, const std::string& bytes)
{
  AtomicOutput output(path);
  {
    std::ofstream out(output.temporaryPath(), std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out)
    {
      throw std::runtime_error(path + ": write failed");
    }
  }
  output.commit();
}

} // namespace shadelab
