#include "shadelab/MemoryFile.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace shadelab
{

MemoryFile::MemoryFile()
  : Descriptor(::memfd_create("shadelab-output", MFD_CLOEXEC))
{
  if (this->Descriptor < 0)
  {
    throw Error(std::string("cannot create an in-memory file: ") + std::strerror(errno));
  }
  this->Path = "/proc/self/fd/" + std::to_string(this->Descriptor);
}

MemoryFile::~MemoryFile()
{
  ::close(this->Descriptor);
}

std::string MemoryFile::contents() const
{
  struct stat info;
  if (::fstat(this->Descriptor, &info) != 0)
  {
    throw Error(std::string("cannot read an in-memory file: ") + std::strerror(errno));
  }
  std::string bytes(static_cast<std::size_t>(info.st_size), '\0');
  std::size_t done = 0;
  while (done < bytes.size())
  {
    const ssize_t got = ::pread(this->Descriptor, &bytes[done], bytes.size() - done, static_cast<off_t>(done));
    if (got < 0 && errno == EINTR)
    {
      continue;
    }
    if (got <= 0)
    {
      throw Error(std::string("cannot read an in-memory file: ") + std::strerror(got < 0 ? errno : EIO));
    }
    done += static_cast<std::size_t>(got);
  }
  return bytes;
}

} // namespace shadelab
