#ifndef slImageFileCheck_h
#define slImageFileCheck_h
/**
 * @file slImageFileCheck.h
 * @brief Checks an image file's length fields before its library sees it.
 *
 * libpng allocates what a PNG chunk's length field claims, and OpenEXR
 * what a header attribute's size, a preview's width and height, the data
 * window's offset table or a tile's size claim, before either finds that
 * the file ends first: a file of a few hundred bytes can cost
 * gigabytes. slImageReader runs these checks, chosen by the file's
 * signature, before OpenImageIO opens the file. Each reads the file once
 * and allocates nothing that its fields claim. Internal to ShadeLab::IO.
 */

#include <string>

/// The problem with the image file @p fileName that would make its library
/// allocate beyond the file, or "" when there is none (also for formats
/// without a check, and for files that cannot be opened: the reader says
/// why). The problem does not name the file; it names the byte offset.
std::string slImageFileProblem(const std::string& fileName);

/// PNG: every chunk up to IEND (or the end of the file) fits in the file and
/// in the PNG limit of 2^31 - 1 bytes, e.g. "PNG chunk 'tEXt' at byte 53
/// declares 1953784832 bytes of data; 140 bytes remain in the file".
/// "" for a file that is not PNG.
std::string slPNGProblem(const std::string& fileName);

/// OpenEXR: every attribute of every header (every part of a multi-part
/// file) has a name and a type of at most 255 bytes that end within the
/// file, and a size that fits in what follows, e.g. "EXR attribute
/// 'comments' (string) at byte 8 declares 1979714868 bytes; 372 bytes
/// remain in the file"; a value of a type OpenEXR knows has that type's
/// layout (fixed sizes, a channel list, a preview's pixels and a string
/// vector's strings that end exactly at the size); the offset table
/// (one 8-byte entry per chunk of every part) fits in the file; and no
/// tile holds more than kMostImageValues values (OpenEXR allocates a tile's
/// buffer when it opens the file). "" for a file that is not OpenEXR.
std::string slEXRProblem(const std::string& fileName);

/// "1 byte remains in the file", "140 bytes remain in the file".
std::string slBytesRemain(unsigned long long count);

/// The most values (pixels x channels) ShadeLab reads from an image, and
/// lets its library decode into one tile: an 8k x 8k RGBA image, 1 GB as
/// floats.
constexpr double kMostImageValues = 268435456.0;

/// "tiles of 32768x32767 pixels of 1 channel, more than ShadeLab reads
/// (2^28 values)" (@p what "tiles of ", or "" for the image) when @p width x
/// @p height x @p channels exceeds kMostImageValues; else "".
std::string slTooManyValues(const std::string& what, double width, double height, double channels);

#endif
