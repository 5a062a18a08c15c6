#ifndef shadelab_MemoryFile_h
#define shadelab_MemoryFile_h
/**
 * @file MemoryFile.h
 * @brief A file that lives in memory (memfd), for writers that only take a
 * file name.
 *
 * VTK's and OpenImageIO's writers do not all report a failed write (a full
 * disk can leave a truncated file behind a "success"). ShadeLab lets them
 * write to a MemoryFile, where writing cannot run out of disk, and then
 * writes the bytes itself through AtomicOutput, which checks every step.
 */

#include "shadelab/Error.h"

#include <string>

namespace shadelab
{

class MemoryFile
{
public:
  /// Creates an empty file in memory. Throws shadelab::Error.
  MemoryFile();
  ~MemoryFile();
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;

  /// A path that opens this file ("/proc/self/fd/N"); it has no extension,
  /// so a writer must be told its format some other way.
  const std::string& path() const { return this->Path; }

  /// Everything written to it so far. Throws shadelab::Error.
  std::string contents() const;

private:
  int Descriptor = -1;
  std::string Path;
};

} // namespace shadelab

#endif
