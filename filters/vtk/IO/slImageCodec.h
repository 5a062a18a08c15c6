#ifndef slImageCodec_h
#define slImageCodec_h
/**
 * @file slImageCodec.h
 * @brief What slImageReader and slImageWriter ask of OpenImageIO, behind a
 * library loaded on first use.
 *
 * OpenImageIO brings 261 shared libraries (codecs, DICOM, video) whose
 * loading and relocation take about a quarter of a second at every start
 * of a program that links it, used or not. ShadeLab::IO therefore does not
 * link it: the functions below live in libShadeLabImageCodec.so (a module
 * beside libShadeLabIO), which slLoadImageCodec() opens the first time an
 * image is read or written. Internal to ShadeLab::IO.
 */

#include <string>

/// Size and kind of an image file, from its header.
struct slImageHeader
{
  int Width = 0;
  int Height = 0;
  int Channels = 0;
  bool EightBit = false; ///< 8-bit unsigned values (otherwise read as float)
  /// The size of a tile in a tiled file, 0 x 0 otherwise: the library
  /// decodes a whole tile into a buffer of its own, whatever the image's
  /// size.
  int TileWidth = 0;
  int TileHeight = 0;
};

/// The image functions; every one returns false with a one-line reason in
/// @p error (which may be empty when the library gives none). A C-style
/// interface on purpose: no exception crosses the dlopen boundary;
/// slImageReader and slImageWriter turn a false into their VTK error.
struct slImageCodec
{
  /// The header of @p path.
  bool (*ReadHeader)(const std::string& path, slImageHeader& header, std::string& error);
  /// Every pixel of @p path, bottom row first (VTK's order), as unsigned
  /// char (@p asFloat false; the file must be 8-bit) or float, into
  /// @p pixels (@p expected width x height x channels values). Fails,
  /// writing nothing, when the file's header (size, channels, tiles) no
  /// longer matches @p expected.
  bool (*ReadPixels)(
    const std::string& path, const slImageHeader& expected, bool asFloat, void* pixels, std::string& error);
  /// Encodes @p pixels (bottom row first; unsigned char or float) in the
  /// format named by @p format ("png", "exr", ...) into the file @p path.
  bool (*Write)(const std::string& path, const std::string& format, int width, int height, int channels,
    bool isFloat, const void* pixels, std::string& error);
};

/// The codec, loaded on the first call; nullptr with the reason in @p error
/// when libShadeLabImageCodec.so cannot be loaded.
const slImageCodec* slLoadImageCodec(std::string& error);

/// The symbol the codec library exports.
extern "C" const slImageCodec* slImageCodecOpenImageIO();

#endif
