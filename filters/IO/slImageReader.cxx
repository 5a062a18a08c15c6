#include "slImageReader.h"

#include "slImageFileCheck.h"
#include "slStderrCapture.h"

#include "shadelab/PrintableText.h"

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkUnsignedCharArray.h>

#include <filesystem>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imagecache.h>

vtkStandardNewMacro(slImageReader);

namespace
{
/// The most values (pixels x channels) read: an 8k x 8k RGBA image, 1 GB
/// as floats. A
/// header claiming more is rejected before anything is allocated.
constexpr double kMaximumValues = 268435456.0;

/// Drops what OpenImageIO's shared cache holds for @p name: the file may have
/// changed since it was last read in this process, and a stale spec read
/// against new contents reads outside them.
void forgetCached(const std::string& name)
{
  OIIO::ImageCache::create(true)->invalidate(OIIO::ustring(name), true);
}
} // namespace

slImageReader::slImageReader()
{
  this->SetNumberOfInputPorts(0);
}

slImageReader::~slImageReader()
{
  this->SetFileName(nullptr);
}

int slImageReader::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // The extent is only known after reading; report it here from the header.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int extent[6] = { 0, -1, 0, -1, 0, 0 };
  // A file whose length fields reach past its end is reported by RequestData;
  // its header is not read here, as its library would allocate what they claim.
  if (this->FileName && slImageFileProblem(this->FileName).empty())
  {
    const slStderrCapture quiet;
    forgetCached(this->FileName);
    OIIO::ImageBuf probe(this->FileName);
    if (probe.init_spec(this->FileName, 0, 0))
    {
      extent[1] = probe.spec().width - 1;
      extent[3] = probe.spec().height - 1;
    }
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  return 1;
}

int slImageReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  output->Initialize();
  this->ErrorMessage.clear();
  const std::string name = this->FileName ? this->FileName : "";
  if (name.empty())
  {
    this->ErrorMessage = "(no file name): no image file given";
    vtkErrorMacro(<< this->ErrorMessage);
    return 0;
  }

  std::error_code ignored;
  if (std::filesystem::is_directory(name, ignored))
  {
    this->ErrorMessage = name + ": cannot read image: it is a directory";
    vtkErrorMacro(<< this->ErrorMessage);
    return 0;
  }
  const std::string fileProblem = slImageFileProblem(name);
  if (!fileProblem.empty())
  {
    this->ErrorMessage = name + ": cannot read image: " + fileProblem;
    vtkErrorMacro(<< this->ErrorMessage);
    return 0;
  }
  // The image libraries' own lines on stderr are held back: the problem is
  // reported once, in ErrorMessage.
  slStderrCapture quiet;
  forgetCached(name);
  OIIO::ImageBuf image(name);
  const bool haveSpec = image.init_spec(name, 0, 0);
  const bool is8Bit = haveSpec && image.spec().format == OIIO::TypeDesc::UINT8;
  const OIIO::TypeDesc type = is8Bit && !this->OutputFloat ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
  std::string reason;
  if (haveSpec && static_cast<double>(image.spec().width) * image.spec().height * image.spec().nchannels > kMaximumValues)
  {
    reason = "its header declares " + std::to_string(image.spec().width) + "x" + std::to_string(image.spec().height) +
      " pixels of " + std::to_string(image.spec().nchannels) + " channels, more than ShadeLab reads (2^28 values)";
  }
  else if (!image.read(0, 0, /*force*/ true, type))
  {
    reason = image.geterror();
    if (reason.empty())
    {
      reason = quiet.Text();
    }
    for (char& c : reason)
    {
      c = c == '\n' ? ' ' : c;
    }
    reason = reason.empty() ? "unknown format" : shadelab::printableText(reason, 200);
  }
  if (!reason.empty())
  {
    this->ErrorMessage = name + ": cannot read image: " + reason;
    vtkErrorMacro(<< this->ErrorMessage);
    return 0;
  }
  // OpenImageIO's row 0 is the top of the picture; VTK's is the bottom.
  OIIO::ImageBuf flipped = OIIO::ImageBufAlgo::flip(image);

  const OIIO::ImageSpec& spec = flipped.spec();
  const int channels = spec.nchannels;
  const vtkIdType pixels = static_cast<vtkIdType>(spec.width) * spec.height;
  vtkSmartPointer<vtkDataArray> scalars;
  if (type == OIIO::TypeDesc::UINT8)
  {
    scalars = vtkSmartPointer<vtkUnsignedCharArray>::New();
  }
  else
  {
    scalars = vtkSmartPointer<vtkFloatArray>::New();
  }
  scalars->SetName("ImageScalars");
  scalars->SetNumberOfComponents(channels);
  scalars->SetNumberOfTuples(pixels);
  flipped.get_pixels(OIIO::ROI::All(), type, scalars->GetVoidPointer(0));

  output->SetExtent(0, spec.width - 1, 0, spec.height - 1, 0, 0);
  output->GetPointData()->SetScalars(scalars);
  return 1;
}

void slImageReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "OutputFloat: " << this->OutputFloat << "\n";
}
