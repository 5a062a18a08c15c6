#ifndef shadelab_AtomicFile_h
#define shadelab_AtomicFile_h
/**
 * @file AtomicFile.h
 * @brief All-or-nothing output files: write to a temporary file beside the
 * target, then rename it over the target.
 *
 * A failed or interrupted write therefore never leaves a half-written file and
 * never destroys an existing one. Used for every file ShadeLab writes.
 */

#include <string>

namespace shadelab
{

/// A temporary file in the target's folder that becomes the target on commit().
/// The temporary name keeps the target's extension, so writers that choose the
/// format by extension (OpenImageIO, VTK) behave as for the target.
class AtomicOutput
{
public:
  /// Creates the temporary file. Throws std::runtime_error naming @p target
  /// if its folder is not writable.
  explicit AtomicOutput(std::string target);
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  /// Where to write the content.
  const std::string& temporaryPath() const { return this->Temporary; }
  const std::string& targetPath() const { return this->Target; }

  /// Renames the temporary file to the target. Throws std::runtime_error.
  void commit();

private:
  std::string Target;
  std::string Temporary;
  bool Committed = false;
};

/// Writes @p bytes to @p path through an AtomicOutput. Throws std::runtime_error.
void writeFileAtomically(const std::string& path, const std::string& bytes);

} // namespace shadelab

#endif
