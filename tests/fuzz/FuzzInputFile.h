// The fuzz input as a file named with the extension under test: ShadeLab's
// readers take file names. One file per process, rewritten for each input.
#ifndef FuzzInputFile_h
#define FuzzInputFile_h

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

inline std::string fuzzInputFile(const uint8_t* data, size_t size, const char* extension)
{
  const char* dir = std::getenv("TMPDIR");
  const std::string path = std::string(dir && *dir ? dir : "/tmp") + "/shadelab-fuzz-" + std::to_string(getpid()) + extension;
  if (FILE* f = std::fopen(path.c_str(), "wb"))
  {
    std::fwrite(data, 1, size, f);
    std::fclose(f);
  }
  return path;
}

#endif
