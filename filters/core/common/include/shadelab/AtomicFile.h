#ifndef shadelab_AtomicFile_h
#define shadelab_AtomicFile_h
/**
 * @file AtomicFile.h
 * @brief All-or-nothing output files: write to a temporary file beside the
 * target, sync it, then rename it over the target.
 *
 * A failed or interrupted write therefore never leaves a half-written file and
 * never destroys an existing one. Used for every file ShadeLab writes.
 *
 * The temporary file is named `.NAME.partial-XXXXXX.EXT` (NAME cut short when
 * the whole would exceed the folder's NAME_MAX) and is held under an exclusive
 * flock() while it exists. A process killed mid-write leaves it behind
 * unlocked: the next AtomicOutput for the same target removes such files,
 * never one another live process still holds.
 */

#include "shadelab/Error.h"

#include <cstddef>
#include <string>

namespace shadelab
{

/// A temporary file in the target's folder that becomes the target on commit().
class AtomicOutput
{
public:
  /// Removes stale temporary files of @p target, then creates and locks its
  /// own. Throws shadelab::Error naming @p target and the system's reason
  /// if its folder is not writable.
  explicit AtomicOutput(std::string target);
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  const std::string& temporaryPath() const { return this->Temporary; }
  const std::string& targetPath() const { return this->Target; }

  /// Writes @p size bytes at @p data to the temporary file, syncs it to the
  /// disk, renames it to the target and syncs the folder. Throws
  /// shadelab::Error "TARGET: cannot write output file: REASON" (REASON is
  /// the system's, e.g. "No space left on device"); the target is then as
  /// before and the temporary file is removed by the destructor.
  void commit(const char* data, std::size_t size);

  /// Appends @p size bytes at @p data to the temporary file, for output
  /// written in pieces; commit() then makes it the target. Throws
  /// shadelab::Error as commit(data, size).
  void write(const char* data, std::size_t size);

  /// Syncs what write() wrote, renames it to the target and syncs the
  /// folder. Throws shadelab::Error as commit(data, size).
  void commit();

  /// As commit(data, size) for a temporary file another writer filled through
  /// temporaryPath(), which must now hold exactly @p expectedSize bytes: a
  /// writer that does not notice a failed write leaves fewer. The message then
  /// gives the system's reason when it can find one (it asks the file system
  /// for the missing space), else the two sizes.
  void commitWritten(long long expectedSize);

private:
  [[noreturn]] void fail(const std::string& what, int error) const;

  std::string Target;
  std::string Temporary;
  int Descriptor = -1;
  bool Committed = false;
};

/// Writes @p bytes to @p path through an AtomicOutput. Throws shadelab::Error.
void writeFileAtomically(const std::string& path, const std::string& bytes);

/// The name AtomicOutput gives the temporary files of @p target, as the part
/// before the six random characters and the part after them (folder included
/// in the first). Both together stay within @p nameMax bytes.
struct TemporaryName
{
  std::string prefix;
  std::string suffix;
};
TemporaryName temporaryNameFor(const std::string& target, std::size_t nameMax);

} // namespace shadelab

#endif
