#include "slImageCodec.h"

#include <dlfcn.h>

#include <mutex>

namespace
{
/// The folder of the library this function is in (libShadeLabIO, or a
/// program or plugin it is linked into), with a trailing slash.
std::string ownFolder()
{
  Dl_info info{};
  if (!dladdr(reinterpret_cast<void*>(&ownFolder), &info) || !info.dli_fname)
  {
    return "";
  }
  const std::string path = info.dli_fname;
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}
} // namespace

const slImageCodec* slLoadImageCodec(std::string& error)
{
  static std::once_flag once;
  static const slImageCodec* codec = nullptr;
  static std::string problem;
  std::call_once(once, [] {
    const std::string path = ownFolder() + "libShadeLabImageCodec.so";
    void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!library)
    {
      const char* reason = dlerror();
      problem = "cannot load ShadeLab's image library: " + std::string(reason ? reason : path);
      return;
    }
    using Entry = const slImageCodec* (*)();
    auto entry = reinterpret_cast<Entry>(dlsym(library, "slImageCodecOpenImageIO"));
    codec = entry ? entry() : nullptr;
    if (!codec)
    {
      problem = "cannot load ShadeLab's image library: " + path + " has no slImageCodecOpenImageIO";
    }
  });
  error = problem;
  return codec;
}
