#include "ImageComparison.h"

#include "slImageReader.h"
#include "slImageWriter.h"
#include "VTKErrors.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace regression
{
namespace
{
/// An RGB image as 8-bit levels, top row first.
struct Levels
{
  int width = 0, height = 0;
  std::vector<unsigned char> rgb; ///< 3 per pixel

  OIIO::ImageBuf buffer() const
  {
    OIIO::ImageBuf out(OIIO::ImageSpec(this->width, this->height, 3, OIIO::TypeDesc::UINT8));
    out.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, this->rgb.data());
    return out;
  }
};

/// The RGB channels of a VTK image (row 0 at the bottom) as levels: 8-bit
/// values as they are, others (in [0, 1]) rounded to the nearest level.
Levels levelsOf(vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  const double scale = scalars->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 : 255.0;
  Levels levels{ dims[0], dims[1], std::vector<unsigned char>(static_cast<size_t>(3) * dims[0] * dims[1]) };
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      const vtkIdType id = static_cast<vtkIdType>(y) * dims[0] + x;
      for (int c = 0; c < 3; ++c)
      {
        const double level = std::round(std::clamp(scalars->GetComponent(id, c) * scale, 0.0, 255.0));
        levels.rgb[3 * (static_cast<size_t>(dims[1] - 1 - y) * dims[0] + x) + c] = static_cast<unsigned char>(level);
      }
    }
  }
  return levels;
}

std::string writeImage(const OIIO::ImageBuf& buffer, const std::string& path)
{
  OIIO::ImageBuf out = buffer;
  return out.write(path, OIIO::TypeDesc::UINT8) ? std::string() : out.geterror();
}
} // namespace

Verdict compareWithBaseline(vtkImageData* candidate, const std::string& baselinePath,
  const std::string& failureFolder, const std::string& name)
{
  Verdict verdict;
  OIIO::ImageBuf file(baselinePath);
  if (!file.read(0, 0, true, OIIO::TypeDesc::UINT8) || file.spec().nchannels < 3)
  {
    verdict.message = baselinePath + ": no readable baseline (create it with SHADELAB_UPDATE_BASELINES=1)";
    return verdict;
  }
  Levels baseline{ file.spec().width, file.spec().height,
    std::vector<unsigned char>(static_cast<size_t>(3) * file.spec().width * file.spec().height) };
  file.get_pixels(OIIO::ROI(0, baseline.width, 0, baseline.height, 0, 1, 0, 3), OIIO::TypeDesc::UINT8,
    baseline.rgb.data());
  const Levels image = levelsOf(candidate);
  const bool sameSize = baseline.width == image.width && baseline.height == image.height;
  verdict.pixels = static_cast<long>(image.width) * image.height;
  if (sameSize)
  {
    // In whole levels, so that "more than 2/255" means 3 levels or more,
    // whatever rounding a conversion to float would bring.
    int largest = 0;
    for (size_t p = 0; p < image.rgb.size(); p += 3)
    {
      int pixel = 0;
      for (size_t c = p; c < p + 3; ++c)
      {
        pixel = std::max(pixel, std::abs(static_cast<int>(image.rgb[c]) - static_cast<int>(baseline.rgb[c])));
      }
      verdict.failingPixels += pixel > PixelThresholdLevels ? 1 : 0;
      largest = std::max(largest, pixel);
    }
    verdict.maxError = largest / 255.0;
    verdict.passed = verdict.failingPixels <= AllowedFailingFraction * verdict.pixels;
  }
  std::ostringstream message;
  if (!sameSize)
  {
    message << name << ": size " << image.width << "x" << image.height << " differs from the baseline's "
            << baseline.width << "x" << baseline.height;
  }
  else
  {
    message << name << ": " << verdict.failingPixels << " of " << verdict.pixels << " pixels differ by more than "
            << PixelThresholdLevels << "/255 (allowed " << static_cast<long>(AllowedFailingFraction * verdict.pixels)
            << "), max error " << verdict.maxError * 255.0 << "/255";
  }
  if (!verdict.passed)
  {
    const std::string stem = failureFolder + "/" + name;
    message << "; candidate " << stem << ".candidate.png";
    writeImage(image.buffer(), stem + ".candidate.png");
    if (sameSize)
    {
      OIIO::ImageBuf diff = OIIO::ImageBufAlgo::absdiff(image.buffer(), baseline.buffer());
      diff = OIIO::ImageBufAlgo::mul(diff, 8.0f);
      writeImage(diff, stem + ".diff.png");
      message << ", diff " << stem << ".diff.png";
    }
  }
  verdict.message = message.str();
  return verdict;
}

std::string writeBaseline(vtkImageData* candidate, const std::string& baselinePath)
{
  vtkNew<slImageWriter> writer;
  writer->SetInputData(candidate);
  writer->SetFileName(baselinePath.c_str());
  return callError(writer, [&] { return writer->Write(); });
}

} // namespace regression
