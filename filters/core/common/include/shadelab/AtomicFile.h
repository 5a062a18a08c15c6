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
 *
 * A program that calls removeTemporaryFilesOnSignals() leaves none behind when
 * SIGINT, SIGTERM or SIGHUP kills it: see there.
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
  int Slot = -1; ///< in the registry of removeTemporaryFilesOnSignals(), -1 if none
};

/// For programs, called once at their start (again does nothing): from then
/// on SIGINT, SIGTERM and SIGHUP first unlink the temporary file of every
/// AtomicOutput alive in the process, whatever its thread or library, then
/// do what they did before: kill the process as by default (the handler
/// re-raises the signal with the default action, so the exit status says the
/// signal killed it), or call the handler the program had installed (which, if
/// it lets the program go on, makes those outputs fail: their files are gone;
/// the targets stay as they were). A signal the program ignores when it calls
/// this (`nohup`, a shell's background job) stays ignored.
///
/// Thread-safe: an output's temporary file is registered from its creation
/// (with the three signals blocked in its thread meanwhile) to its rename or
/// removal, in a fixed registry of 64 outputs at once (one more is not
/// registered, and a signal leaves its file for the next write of its target
/// to remove) shared by every library's copy of this code: the one symbol
/// they export. While a handler runs, other threads wait before creating a
/// temporary file or reporting the one it removed. The handler uses only
/// lock-free atomics, unlink(), signal(), pthread_sigmask() and raise(), so
/// it may interrupt any thread anywhere (inside malloc, a lock, the
/// registry's own update).
///
/// Libraries never call it: a host (Python, ParaView) owns its signals, and
/// without the call AtomicOutput registers nothing.
void removeTemporaryFilesOnSignals();

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
