#include "BenchMemory.h"

#include <fstream>
#include <malloc.h>
#include <string>

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
  malloc_trim(0);
  if (!(std::ofstream("/proc/self/clear_refs") << "5")) // resets VmHWM to VmRSS
  {
    return -1;
  }
  const long long before = statusField("VmRSS");
  job();
  const long long peak = statusField("VmHWM");
  return before < 0 || peak < 0 ? -1 : peak - before;
}
