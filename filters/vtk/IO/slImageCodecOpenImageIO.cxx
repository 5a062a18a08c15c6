// libShadeLabImageCodec.so: slImageCodec through OpenImageIO.
#include "slImageCodec.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imagecache.h>

namespace
{
void forget(const std::string& path)
{
  OIIO::ImageCache::create(true)->invalidate(OIIO::ustring(path), true);
}

bool readHeader(const std::string& path, slImageHeader& header, std::string& error)
{
  OIIO::ImageBuf image(path);
  if (!image.init_spec(path, 0, 0))
  {
    error = image.geterror();
    return false;
  }
  header.Width = image.spec().width;
  header.Height = image.spec().height;
  header.Channels = image.spec().nchannels;
  header.EightBit = image.spec().format == OIIO::TypeDesc::UINT8;
  return true;
}

bool readPixels(const std::string& path, bool asFloat, void* pixels, std::string& error)
{
  const OIIO::TypeDesc type = asFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
  OIIO::ImageBuf image(path);
  if (!image.read(0, 0, /*force*/ true, type))
  {
    error = image.geterror();
    return false;
  }
  // OpenImageIO's row 0 is the top of the picture; VTK's is the bottom.
  const OIIO::ImageBuf flipped = OIIO::ImageBufAlgo::flip(image);
  if (!flipped.get_pixels(OIIO::ROI::All(), type, pixels))
  {
    error = flipped.geterror();
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

const slImageCodec codec{ &forget, &readHeader, &readPixels, &write };
} // namespace

extern "C" const slImageCodec* slImageCodecOpenImageIO()
{
  return &codec;
}
