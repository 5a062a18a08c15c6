#ifndef shadelab_InputFile_h
#define shadelab_InputFile_h
/**
 * @file InputFile.h
 * @brief The one check every reader makes before opening an input file
 * (mesh, scene, image, .brdf): that it is a regular file; and the reason
 * it gives when the opening fails.
 *
 * A directory opens on Linux and reads as nothing; a device such as
 * /dev/zero never ends, and a FIFO or socket blocks until a writer comes.
 * A reader given one would fail with a misleading parse error, grow its
 * buffer until memory runs out, or hang.
 */

#include <string>

namespace shadelab
{

/// Why @p path is no input file: "is a directory, not @p what" (@p what
/// is e.g. "a mesh file"), or "is not a regular file (a device, pipe or
/// socket)"; symbolic links are followed. "" for a regular file, and for a
/// path that cannot be looked at (missing, no permission), which the
/// reader's opening of it then reports.
std::string inputFileProblem(const std::string& path, const std::string& what);

/// Why @p path cannot be opened for reading, as the system says it ("No
/// such file or directory", "Permission denied", "Not a directory"), for the
/// line of a reader whose opening failed: a stream keeps no reason, so the
/// file is opened once more to ask. "it could not be opened" if that
/// opening succeeds (the file came into being meanwhile).
std::string openFailureReason(const std::string& path);

} // namespace shadelab

#endif
