#include "shadelab/AtomicFile.h"

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <stdexcept>
#include <sys/file.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace shadelab
{
namespace
{
const char* const PartialMarker = ".partial-";
const std::size_t RandomLength = 6; // mkstemps' XXXXXX

std::string folderOf(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

/// The longest file name the target's folder allows (NAME_MAX unless the
/// file system says otherwise).
std::size_t nameMaxOf(const std::string& folder)
{
  const long max = ::pathconf(folder.empty() ? "." : folder.c_str(), _PC_NAME_MAX);
  return max > 0 ? static_cast<std::size_t>(max) : NAME_MAX;
}

/// Removes every unlocked temporary file of @p name in its folder: such a file
/// belongs to no live AtomicOutput (each holds its lock until it is gone).
void removeStaleTemporaries(const TemporaryName& name)
{
  const std::string folder = folderOf(name.prefix);
  const std::string prefix = name.prefix.substr(folder.size());
  DIR* dir = ::opendir(folder.empty() ? "." : folder.c_str());
  if (!dir)
  {
    return; // creating the temporary file reports the reason
  }
  while (const dirent* entry = ::readdir(dir))
  {
    const std::string file = entry->d_name;
    if (file.size() != prefix.size() + RandomLength + name.suffix.size() || file.compare(0, prefix.size(), prefix) != 0 ||
      file.compare(file.size() - name.suffix.size(), name.suffix.size(), name.suffix) != 0)
    {
      continue;
    }
    const std::string path = folder + file;
    const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0)
    {
      continue;
    }
    struct stat info;
    if (::fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && ::flock(fd, LOCK_EX | LOCK_NB) == 0)
    {
      ::unlink(path.c_str()); // under the lock: its creator, if any, sees it unlinked and retries
    }
    ::close(fd);
  }
  ::closedir(dir);
}

/// The file a write of @p path replaces: @p path, or where its symbolic
/// links lead, as open() and `cp` write through them; renaming over the link
/// itself would turn it into a plain file and leave its target as it was.
/// A dangling link leads to the file to create. Throws shadelab::Error for
/// a loop of links.
std::string followLinks(const std::string& path)
{
  std::string current = path;
  for (int hops = 0; hops <= 40; ++hops) // Linux's own limit (ELOOP)
  {
    std::vector<char> buffer(PATH_MAX + 1);
    const ssize_t length = ::readlink(current.c_str(), buffer.data(), buffer.size());
    if (length < 0 || static_cast<std::size_t>(length) >= buffer.size())
    {
      return current; // not a link (or nothing there yet): the file itself
    }
    const std::string link(buffer.data(), static_cast<std::size_t>(length));
    current = link[0] == '/' ? link : folderOf(current) + link;
  }
  throw Error(path + ": cannot create output file: " + std::strerror(ELOOP));
}

/// The path through which the open file @p fd can be opened and linked.
std::string descriptorPath(int fd)
{
  return "/proc/self/fd/" + std::to_string(fd);
}

/// An unnamed file in @p folder, open for writing (O_TMPFILE), or -1 where
/// the file system or kernel has none, or /proc cannot name it for linkat()
/// and for writers that take a path.
int openUnnamed(const std::string& folder)
{
  const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  if (fd >= 0 && ::access(descriptorPath(fd).c_str(), W_OK) != 0)
  {
    ::close(fd);
    return -1;
  }
  return fd;
}

/// Six characters of mkstemps' alphabet, at random.
std::string randomCharacters()
{
  static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  unsigned char bytes[RandomLength];
  if (::getrandom(bytes, sizeof bytes, 0) != static_cast<ssize_t>(sizeof bytes))
  {
    // Only a name is at stake: linkat() never replaces a file, so a repeated
    // name is retried, not lost.
    for (std::size_t i = 0; i < RandomLength; ++i)
    {
      bytes[i] = static_cast<unsigned char>(std::rand());
    }
  }
  std::string text(RandomLength, 'X');
  for (std::size_t i = 0; i < RandomLength; ++i)
  {
    text[i] = alphabet[bytes[i] % (sizeof alphabet - 1)];
  }
  return text;
}
} // namespace

TemporaryName temporaryNameFor(const std::string& target, std::size_t nameMax)
{
  const std::string folder = folderOf(target);
  const std::string name = target.substr(folder.size());
  const std::size_t dot = name.find_last_of('.');
  std::string extension = dot == std::string::npos || dot == 0 ? std::string() : name.substr(dot);
  std::string stem = name.substr(0, name.size() - extension.size());
  const std::size_t fixed = 1 + std::strlen(PartialMarker) + RandomLength;
  if (fixed + extension.size() > nameMax)
  {
    extension.clear(); // no writer takes such an extension; the name must still fit
  }
  stem.resize(std::min(stem.size(), nameMax - fixed - extension.size()));
  return { folder + "." + stem + PartialMarker, extension };
}

AtomicOutput::AtomicOutput(std::string target, TemporaryKind kind)
  : Target(std::move(target))
{
  this->Destination = followLinks(this->Target);
  this->Name = temporaryNameFor(this->Destination, nameMaxOf(folderOf(this->Destination)));
  const TemporaryName& name = this->Name;
  removeStaleTemporaries(name);

  if (kind == TemporaryKind::Unnamed)
  {
    this->Descriptor = openUnnamed(folderOf(this->Destination));
    if (this->Descriptor >= 0)
    {
      // Its name, given at commit(), must not look stale to another writer.
      ::flock(this->Descriptor, LOCK_EX);
      this->Unnamed = true;
      this->Temporary = descriptorPath(this->Descriptor);
    }
  }
  // Another process's cleanup may unlink the file between mkstemps and flock;
  // the unlinked file then has no links left, and a new one is made.
  for (int attempt = 0; this->Descriptor < 0; ++attempt)
  {
    std::string pattern = name.prefix + std::string(RandomLength, 'X') + name.suffix;
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    const int fd = ::mkostemps(buffer.data(), static_cast<int>(name.suffix.size()), O_CLOEXEC);
    if (fd < 0)
    {
      throw Error(this->Target + ": cannot create output file: " + std::strerror(errno));
    }
    // The lock is advisory: were flock() unsupported here, writing still works.
    ::flock(fd, LOCK_EX);
    struct stat info;
    if (::fstat(fd, &info) == 0 && info.st_nlink == 0 && attempt < 10)
    {
      ::close(fd);
      continue;
    }
    this->Descriptor = fd;
    this->Temporary = buffer.data();
  }

  // mkstemps creates the file 0600; give it the mode a plain open() would
  // (0666 less the umask), or the mode of the file it will replace.
  struct stat existing;
  mode_t mode;
  if (::stat(this->Destination.c_str(), &existing) == 0)
  {
    mode = existing.st_mode & 07777;
  }
  else
  {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  ::fchmod(this->Descriptor, mode);
}

AtomicOutput::~AtomicOutput()
{
  if (!this->Committed && !this->Unnamed && !this->Temporary.empty())
  {
    ::unlink(this->Temporary.c_str());
  }
  if (this->Descriptor >= 0)
  {
    ::close(this->Descriptor);
  }
}

void AtomicOutput::fail(const std::string& what, int error) const
{
  throw Error(this->Target + ": " + what + ": " + std::strerror(error));
}

void AtomicOutput::commit(const char* data, std::size_t size)
{
  this->write(data, size);
  this->commit();
}

void AtomicOutput::write(const char* data, std::size_t size)
{
  while (size > 0)
  {
    const ssize_t written = ::write(this->Descriptor, data, size);
    if (written < 0 && errno == EINTR)
    {
      continue;
    }
    if (written <= 0)
    {
      this->fail("cannot write output file", written < 0 ? errno : ENOSPC);
    }
    data += written;
    size -= static_cast<std::size_t>(written);
  }
}

void AtomicOutput::commitWritten(long long expectedSize)
{
  struct stat info;
  if (::fstat(this->Descriptor, &info) != 0)
  {
    this->fail("cannot write output file", errno);
  }
  if (info.st_size != expectedSize)
  {
    if (info.st_size < expectedSize)
    {
      const int error = ::posix_fallocate(this->Descriptor, 0, static_cast<off_t>(expectedSize));
      if (error != 0)
      {
        this->fail("cannot write output file", error);
      }
    }
    throw Error(this->Target + ": cannot write output file: the writer wrote " +
      std::to_string(info.st_size) + " bytes of " + std::to_string(expectedSize));
  }
  this->commit();
}

void AtomicOutput::commit()
{
  // The data must be on the disk before the new name points at it, or a crash
  // right after the rename could leave an empty or partial file under it.
  if (::fsync(this->Descriptor) != 0)
  {
    this->fail("cannot write output file", errno);
  }
  const std::string named = this->Unnamed ? this->giveName() : this->Temporary;
  if (::rename(named.c_str(), this->Destination.c_str()) != 0)
  {
    const int error = errno;
    if (this->Unnamed)
    {
      ::unlink(named.c_str());
    }
    this->fail("cannot write output file", error);
  }
  this->Committed = true;
  // The rename itself is durable once the folder is synced.
  const std::string folder = folderOf(this->Destination);
  const int dir = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0)
  {
    ::fsync(dir);
    ::close(dir);
  }
}

std::string AtomicOutput::giveName() const
{
  // linkat() never replaces a file: a name another file took is retried.
  for (int attempt = 0;; ++attempt)
  {
    const std::string named = this->Name.prefix + randomCharacters() + this->Name.suffix;
    if (::linkat(AT_FDCWD, this->Temporary.c_str(), AT_FDCWD, named.c_str(), AT_SYMLINK_FOLLOW) == 0)
    {
      return named;
    }
    if (errno != EEXIST || attempt == 100)
    {
      this->fail("cannot write output file", errno);
    }
  }
}

void writeFileAtomically(const std::string& path, const std::string& bytes)
{
  AtomicOutput output(path);
  output.commit(bytes.data(), bytes.size());
}

} // namespace shadelab
