#include "BenchMemory.h"

#include <fstream>
#include <malloc.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace
{
/// A "VmXXX:   1234 kB" field of /proc/self/status, in bytes.
long long statusField(const std::string& name)
{
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
  {
    if (line.rfind(name + ":", 0) == 0)
    {
      return std::stoll(line.substr(name.size() + 1)) * 1024;
    }
  }
  return -1;
}
} // namespace

long long slPeakMemoryAbove(const std::function<void()>& job)
{
  int fds[2];
  if (pipe(fds) != 0)
  {
    return -1;
  }
  const pid_t pid = fork();
  if (pid == 0)
  {
    close(fds[0]);
    malloc_trim(0); // memory freed earlier must not be reused unseen
    std::ofstream("/proc/self/clear_refs") << "5"; // resets VmHWM to VmRSS
    const long long before = statusField("VmRSS");
    job();
    const long long peak = statusField("VmHWM") - before;
    (void)!write(fds[1], &peak, sizeof(peak));
    _exit(0);
  }
  close(fds[1]);
  long long peak = -1;
  if (read(fds[0], &peak, sizeof(peak)) != sizeof(peak))
  {
    peak = -1;
  }
  close(fds[0]);
  waitpid(pid, nullptr, 0);
  return peak;
}
