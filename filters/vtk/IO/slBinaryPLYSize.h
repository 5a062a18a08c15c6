#ifndef slBinaryPLYSize_h
#define slBinaryPLYSize_h
/**
 * @file slBinaryPLYSize.h
 * @brief The size a complete binary PLY file must have, from its own header.
 *
 * vtkPLYWriter does not notice a failed write (a full disk leaves a
 * truncated file behind a success), and VTK 9.1's "write to string" mode
 * returns nothing; slMeshWriter therefore checks the written file's size
 * against what its header promises.
 */

#include <cstdint>
#include <string>

/// The byte count of a complete binary PLY file whose header is at the start
/// of @p bytes (at least its header), given @p listEntries, the total number
/// of entries of the file's one list property (the face corners). -1 if the
/// header is not a binary PLY header slBinaryPLYSize understands.
std::int64_t slBinaryPLYSize(const std::string& bytes, std::int64_t listEntries);

#endif
