#include "shadelab/AtomicFile.h"

#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <pthread.h>
#include <sched.h>
#include <stdexcept>
#include <sys/file.h>
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
} // namespace

// The temporary files a fatal signal removes (removeTemporaryFilesOnSignals).
//
// The handler may interrupt any thread anywhere, even inside malloc or inside
// an update of this registry, so the registry is a fixed array of fixed path
// buffers, each guarded by one lock-free atomic, and the handler calls nothing
// but unlink, signal, pthread_sigmask and raise.
//
// One registry per process: CommonCore is linked, hidden, into the programs
// and into several shared libraries, each with its own copy of this file, and
// a program's outputs are written by the copy in libShadeLabIO as much as by
// its own. So the registry is the one symbol CommonCore exports (C linkage, no
// constructor: zero-initialized, usable before any static initializer): the
// dynamic linker binds every copy to one instance, the program's. The name
// carries the layout's version; a new layout needs a new name.
namespace
{
const std::size_t RegistrySlots = 64; // outputs open at once; beyond, not registered
const int Signals[] = { SIGINT, SIGTERM, SIGHUP };
const long SpinLimit = 100000000; // the handler's waits, bounded (a thread may be stopped)

enum SlotState : int
{
  Free = 0,
  Filling, // its thread is creating the file, the signals blocked: soon Held or Free
  Held,    // path names a live temporary file
  Taken,   // a handler is unlinking it: soon Held again
};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs lock-free atomics");
} // namespace

struct TemporaryFileSlot
{
  std::atomic<int> state;
  char path[PATH_MAX];
};

struct TemporaryFileRegistry
{
  std::atomic<bool> enabled; // the program called removeTemporaryFilesOnSignals()
  std::atomic<int> dying;    // handlers running: no thread creates a temporary file
  struct sigaction previous[3]; // the handlers replaced, per Signals[]
  TemporaryFileSlot slots[RegistrySlots];
};
} // namespace shadelab

extern "C"
{
  __attribute__((visibility("default"))) shadelab::TemporaryFileRegistry shadelab_temporary_files_v1;
}

namespace shadelab
{
namespace
{
TemporaryFileRegistry& registry = shadelab_temporary_files_v1;

/// While a handler on another thread removes the files and kills the process,
/// this thread must neither create a file (the handler may have swept its
/// slot already) nor report the file it lost (the process dies of the signal,
/// not of that error). Returns at once otherwise, or if the handler chained to
/// the program's own one, which let the process go on.
void waitWhileDying()
{
  while (registry.dying.load() > 0)
  {
    ::sched_yield();
  }
}

/// A slot claimed (Filling) for a temporary file about to be created, with
/// SIGINT, SIGTERM and SIGHUP blocked in this thread until hold() or
/// destruction: the file then exists only while registered, and a handler
/// running on another thread meanwhile waits for the slot to leave Filling.
/// Does nothing unless the program enabled the registry.
class SlotClaim
{
public:
  SlotClaim()
  {
    if (!registry.enabled.load())
    {
      return;
    }
    sigset_t block;
    sigemptyset(&block);
    for (const int signo : Signals)
    {
      sigaddset(&block, signo);
    }
    this->Blocked = ::pthread_sigmask(SIG_BLOCK, &block, &this->Saved) == 0;
    for (;;)
    {
      for (std::size_t i = 0; i < RegistrySlots && this->Slot < 0; ++i)
      {
        int expected = Free;
        if (registry.slots[i].state.compare_exchange_strong(expected, Filling))
        {
          this->Slot = static_cast<int>(i);
        }
      }
      // Claim, then look (both sequentially consistent, as the handler's
      // mark, then sweep): the handler waits for this slot, or this thread
      // sees it dying and gives the slot back.
      if (registry.dying.load() == 0)
      {
        return;
      }
      this->freeSlot();
      waitWhileDying();
    }
  }
  ~SlotClaim()
  {
    this->freeSlot(); // creation failed
    if (this->Blocked)
    {
      ::pthread_sigmask(SIG_SETMASK, &this->Saved, nullptr);
    }
  }
  SlotClaim(const SlotClaim&) = delete;
  SlotClaim& operator=(const SlotClaim&) = delete;

  /// Registers @p path in the claimed slot; returns the slot, or -1 if none
  /// (registry off or full, path too long: the file is then only removed by
  /// a later write of the same target, as a killed process's).
  int hold(const std::string& path)
  {
    if (this->Slot < 0 || path.size() >= PATH_MAX)
    {
      return -1;
    }
    const int slot = this->Slot;
    std::memcpy(registry.slots[slot].path, path.c_str(), path.size() + 1);
    registry.slots[slot].state.store(Held); // publishes the path to the handler
    this->Slot = -1;
    return slot;
  }

private:
  void freeSlot()
  {
    if (this->Slot >= 0)
    {
      registry.slots[this->Slot].state.store(Free);
      this->Slot = -1;
    }
  }

  int Slot = -1;
  bool Blocked = false;
  sigset_t Saved;
};

/// Frees @p slot once its file is renamed or removed. Waits out a handler
/// unlinking it on another thread, which must not read a path being reused.
void release(int slot)
{
  if (slot < 0)
  {
    return;
  }
  int expected = Held;
  while (!registry.slots[slot].state.compare_exchange_weak(expected, Free))
  {
    expected = Held;
  }
}

void removeTemporariesAndReraise(int signo, siginfo_t* info, void* context)
{
  const int savedErrno = errno;
  registry.dying.fetch_add(1);
  for (TemporaryFileSlot& slot : registry.slots)
  {
    // Waits for Filling (a file being created) and Taken (another handler
    // unlinking, which may be about to kill the process).
    for (long spin = 0; spin < SpinLimit; ++spin)
    {
      int state = Held;
      if (slot.state.compare_exchange_strong(state, Taken))
      {
        ::unlink(slot.path); // ENOENT if renamed to its target meanwhile: nothing lost
        slot.state.store(Held);
        break;
      }
      if (state == Free)
      {
        break;
      }
    }
  }
  std::size_t index = 0;
  while (Signals[index] != signo)
  {
    ++index;
  }
  const struct sigaction& previous = registry.previous[index];
  if (previous.sa_flags & SA_SIGINFO)
  {
    previous.sa_sigaction(signo, info, context);
  }
  else if (previous.sa_handler != SIG_DFL) // never SIG_IGN: that is not replaced
  {
    previous.sa_handler(signo);
  }
  else
  {
    // Dies of the signal, so the exit status says so, as shells and callers
    // expect; at once, not on return, before another thread goes on.
    ::signal(signo, SIG_DFL);
    ::raise(signo); // pending: blocked while this handler runs
    sigset_t unblock;
    sigemptyset(&unblock);
    sigaddset(&unblock, signo);
    ::pthread_sigmask(SIG_UNBLOCK, &unblock, nullptr);
  }
  registry.dying.fetch_sub(1); // the program's handler let it go on
  errno = savedErrno;
}
} // namespace

void removeTemporaryFilesOnSignals()
{
  if (registry.enabled.exchange(true))
  {
    return; // installed already
  }
  for (std::size_t i = 0; i < sizeof(Signals) / sizeof(Signals[0]); ++i)
  {
    struct sigaction previous;
    if (::sigaction(Signals[i], nullptr, &previous) != 0 ||
      (!(previous.sa_flags & SA_SIGINFO) && previous.sa_handler == SIG_IGN))
    {
      continue; // an ignored signal stays ignored (nohup, background jobs)
    }
    registry.previous[i] = previous; // before the handler can run
    struct sigaction action = {};
    action.sa_sigaction = removeTemporariesAndReraise;
    action.sa_flags = SA_SIGINFO | SA_RESTART;
    sigemptyset(&action.sa_mask);
    for (const int signo : Signals)
    {
      sigaddset(&action.sa_mask, signo); // one handler at a time per thread
    }
    ::sigaction(Signals[i], &action, nullptr);
  }
}

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

AtomicOutput::AtomicOutput(std::string target)
  : Target(std::move(target))
{
  const TemporaryName name = temporaryNameFor(this->Target, nameMaxOf(folderOf(this->Target)));
  removeStaleTemporaries(name);

  // Another process's cleanup may unlink the file between mkstemps and flock;
  // the unlinked file then has no links left, and a new one is made.
  SlotClaim claim; // registered from its creation on, for the signal handler
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
  this->Slot = claim.hold(this->Temporary);

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
  ::fchmod(this->Descriptor, mode);
}

AtomicOutput::~AtomicOutput()
{
  if (!this->Committed && !this->Temporary.empty())
  {
    ::unlink(this->Temporary.c_str());
  }
  release(this->Slot); // after the unlink: a signal in between finds it registered
  if (this->Descriptor >= 0)
  {
    ::close(this->Descriptor);
  }
}

void AtomicOutput::fail(const std::string& what, int error) const
{
  waitWhileDying(); // a signal handler may have removed the file: the signal, not this, ends the process
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
  if (::rename(this->Temporary.c_str(), this->Target.c_str()) != 0)
  {
    this->fail("cannot write output file", errno);
  }
  this->Committed = true;
  release(this->Slot); // after the rename: a signal before it removes the temporary file
  this->Slot = -1;
  // The rename itself is durable once the folder is synced.
  const std::string folder = folderOf(this->Target);
  const int dir = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0)
  {
    ::fsync(dir);
    ::close(dir);
  }
}

void writeFileAtomically(const std::string& path, const std::string& bytes)
{
  AtomicOutput output(path);
  output.commit(bytes.data(), bytes.size());
}

} // namespace shadelab
