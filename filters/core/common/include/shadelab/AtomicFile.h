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
 * The temporary file has no name while it is written (O_TMPFILE): a process
 * killed or interrupted mid-write, by any signal, leaves nothing behind,
 * since the kernel frees a file without a name once it is closed. commit()
 * links it as `.NAME.partial-XXXXXX.EXT` (NAME cut short when the whole
 * would exceed the folder's NAME_MAX) and renames that over the target, a
 * name that lives for two system calls. Where the file system has no
 * O_TMPFILE (or /proc is not mounted), the temporary file carries that name
 * from the start. Either way it is held under an exclusive flock() while it
 * has a name; a process killed while the name exists leaves it behind
 * unlocked, and the next AtomicOutput for the same target removes such
 * files, never one another live process still holds.
 *
 * A target that is a symbolic link is written through: the file it leads
 * to is replaced (the temporary file lies beside that one), and the link
 * stays a link.
 */

#include "shadelab/Error.h"

#include <cstddef>
#include <string>

namespace shadelab
{

/// Whether AtomicOutput's temporary file has a name while it is written.
enum class TemporaryKind
{
  Unnamed, ///< none until commit(), where the file system allows (else Named)
  Named,   ///< `.NAME.partial-XXXXXX.EXT` from the start
};

/// The name AtomicOutput gives the temporary files of @p target, as the part
/// before the six random characters and the part after them (folder included
/// in the first). Both together stay within @p nameMax bytes.
struct TemporaryName
{
  std::string prefix;
  std::string suffix;
};
TemporaryName temporaryNameFor(const std::string& target, std::size_t nameMax);

/// A temporary file in the target's folder that becomes the target on commit().
class AtomicOutput
{
public:
  /// Removes stale temporary files of @p target, then creates its own, of
  /// @p kind. Throws shadelab::Error naming @p target and the system's
  /// reason if its folder is not writable.
  explicit AtomicOutput(std::string target, TemporaryKind kind = TemporaryKind::Unnamed);
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  /// A path through which another writer can open the temporary file: its
  /// name, or /proc/self/fd/N while it has none.
  const std::string& temporaryPath() const { return this->Temporary; }
  const std::string& targetPath() const { return this->Target; }
  /// Whether the temporary file has no name (see TemporaryKind).
  bool unnamed() const { return this->Unnamed; }

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
  /// Links the unnamed file under a new temporary name and returns it.
  std::string giveName() const;

  std::string Target;      ///< as given, for messages
  std::string Destination; ///< the file replaced: Target, its links followed
  TemporaryName Name;
  std::string Temporary;
  int Descriptor = -1;
  bool Unnamed = false;
  bool Committed = false;
};

/// Writes @p bytes to @p path through an AtomicOutput. Throws shadelab::Error.
void writeFileAtomically(const std::string& path, const std::string& bytes);

} // namespace shadelab

#endif
