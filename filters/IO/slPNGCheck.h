#ifndef slPNGCheck_h
#define slPNGCheck_h
/**
 * @file slPNGCheck.h
 * @brief Checks a PNG file's chunk lengths before libpng sees it.
 *
 * libpng allocates what a chunk's length field claims (up to 2 GB) before
 * it finds that the file ends first; a 200-byte file can cost gigabytes.
 * slImageReader runs this check on every file that starts with the PNG
 * signature. Internal to ShadeLab::IO.
 */

#include <string>

/// "" when every chunk of the PNG file @p fileName (up to IEND, or to the
/// end of the file) fits in the file and the PNG limit of 2^31 - 1 bytes;
/// otherwise the first chunk that does not, with its type and byte offset,
/// e.g. "PNG chunk 'tEXt' at byte 53 declares 1953784832 bytes of data; 140
/// bytes remain in the file". Also "" for a file that is not PNG.
std::string slPNGProblem(const std::string& fileName);

#endif
