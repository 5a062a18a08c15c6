// libShadeLabImageCodec.so: slImageCodec through OpenImageIO.
#include "slImageCodec.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <memory>

namespace
{
/// The file opened by whichever OpenImageIO reader recognises it; nullptr
/// with the library's reason in @p error.
std::unique_ptr<OIIO::ImageInput> openImage(const std::string& path, std::string& error)
{
  std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::open(path);
  if (!input)
  {
    error = OIIO::geterror();
  }
  return input;
}

/// @p spec as a header; false for what ShadeLab does not read: an image
/// without pixels, or a volume (DDS, TIFF and others hold width x height x
/// depth pixels, which would not fit the width x height buffer the reader
/// allocates).
bool describe(const OIIO::ImageSpec& spec, slImageHeader& header, std::string& error)
{
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
  {
    error = "it has no pixels: its header declares " + std::to_string(spec.width) + "x" +
      std::to_string(spec.height) + " pixels of " + std::to_string(spec.nchannels) + " channels";
    return false;
  }
  if (spec.depth != 1)
  {
    error = "it holds a volume of " + std::to_string(spec.depth) + " slices; ShadeLab reads 2D images only";
    return false;
  }
  header.Width = spec.width;
  header.Height = spec.height;
  header.Channels = spec.nchannels;
  header.EightBit = spec.format == OIIO::TypeDesc::UINT8;
  header.TileWidth = spec.tile_width;
  header.TileHeight = spec.tile_height;
  return true;
}

bool readHeader(const std::string& path, slImageHeader& header, std::string& error)
{
  const std::unique_ptr<OIIO::ImageInput> input = openImage(path, error);
  return input && describe(input->spec(), header, error);
}

bool readPixels(
  const std::string& path, const slImageHeader& expected, bool asFloat, void* pixels, std::string& error)
{
  // Opened again: the file may have been replaced since its header was read,
  // and only a header that still matches may fill a buffer sized from it.
  const std::unique_ptr<OIIO::ImageInput> input = openImage(path, error);
  slImageHeader header;
  if (!input || !describe(input->spec(), header, error))
  {
    return false;
  }
  if (header.Width != expected.Width || header.Height != expected.Height || header.Channels != expected.Channels ||
    header.TileWidth != expected.TileWidth || header.TileHeight != expected.TileHeight ||
    (!asFloat && !header.EightBit))
  {
    error = "it changed while it was read";
    return false;
  }
  const OIIO::TypeDesc type = asFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
  const OIIO::stride_t pixelBytes = static_cast<OIIO::stride_t>(header.Channels) * type.size();
  const OIIO::stride_t rowBytes = pixelBytes * header.Width;
  // OpenImageIO's row 0 is the top of the picture; VTK's is the bottom: the
  // rows go into the buffer from its last row backwards.
  char* lastRow = static_cast<char*>(pixels) + rowBytes * (header.Height - 1);
  if (!input->read_image(0, 0, 0, header.Channels, type, lastRow, pixelBytes, -rowBytes))
  {
    error = input->geterror();
    return false;
  }
  return true;
}

bool write(const std::string& path, const std::string& format, int width, int height, int channels, bool isFloat,
  const void* pixels, std::string& error)
{
  const OIIO::ImageSpec spec(width, height, channels, isFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  // Wrap the caller's buffer (bottom row first) and flip to top-first.
  const OIIO::ImageBuf wrapped(spec, const_cast<void*>(pixels));
  const OIIO::ImageBuf flipped = OIIO::ImageBufAlgo::flip(wrapped);
  if (!flipped.write(path, OIIO::TypeUnknown, format))
  {
    error = flipped.geterror();
    return false;
  }
  return true;
}

const slImageCodec codec{ &readHeader, &readPixels, &write };
} // namespace

extern "C" const slImageCodec* slImageCodecOpenImageIO()
{
  return &codec;
}
