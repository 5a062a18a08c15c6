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

#include <sstream>

namespace regression
{
namespace
{
/// The RGB channels of a VTK image as an OpenImageIO float buffer, top row first.
OIIO::ImageBuf toImageBuf(vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  OIIO::ImageBuf buffer(OIIO::ImageSpec(dims[0], dims[1], 3, OIIO::TypeDesc::FLOAT));
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      const vtkIdType id = static_cast<vtkIdType>(y) * dims[0] + x;
      float rgb[3];
      const double scale = scalars->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
      for (int c = 0; c < 3; ++c)
      {
        rgb[c] = static_cast<float>(scalars->GetComponent(id, c) * scale);
      }
      buffer.setpixel(x, dims[1] - 1 - y, rgb);
    }
  }
  return buffer;
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
  OIIO::ImageBuf baseline(baselinePath);
  if (!baseline.read(0, 0, true, OIIO::TypeDesc::FLOAT))
  {
    verdict.message = baselinePath + ": no readable baseline (create it with SHADELAB_UPDATE_BASELINES=1)";
    return verdict;
  }
  const OIIO::ImageBuf image = toImageBuf(candidate);
  const bool sameSize = baseline.spec().width == image.spec().width && baseline.spec().height == image.spec().height;
  verdict.pixels = static_cast<long>(image.spec().width) * image.spec().height;
  if (sameSize)
  {
    const OIIO::ImageBufAlgo::CompareResults result =
      OIIO::ImageBufAlgo::compare(image, baseline, PixelThreshold, PixelThreshold / 2.0f, OIIO::ROI(0, image.spec().width, 0, image.spec().height, 0, 1, 0, 3));
    verdict.failingPixels = static_cast<long>(result.nfail);
    verdict.maxError = result.maxerror;
    verdict.passed = verdict.failingPixels <= AllowedFailingFraction * verdict.pixels;
  }
  std::ostringstream message;
  if (!sameSize)
  {
    message << name << ": size " << image.spec().width << "x" << image.spec().height << " differs from the baseline's "
            << baseline.spec().width << "x" << baseline.spec().height;
  }
  else
  {
    message << name << ": " << verdict.failingPixels << " of " << verdict.pixels << " pixels differ by more than 2/255 (allowed "
            << static_cast<long>(AllowedFailingFraction * verdict.pixels) << "), max error " << verdict.maxError * 255.0
            << "/255";
  }
  if (!verdict.passed)
  {
    const std::string stem = failureFolder + "/" + name;
    message << "; candidate " << stem << ".candidate.png";
    writeImage(image, stem + ".candidate.png");
    if (sameSize)
    {
      OIIO::ImageBuf diff = OIIO::ImageBufAlgo::absdiff(image, baseline);
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
