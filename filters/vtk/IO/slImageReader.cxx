#include "slImageReader.h"

#include "slImageCodec.h"
#include "slImageFileCheck.h"
#include "slStderrCapture.h"

#include "shadelab/InputFile.h"
#include "shadelab/PrintableText.h"

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkUnsignedCharArray.h>


vtkStandardNewMacro(slImageReader);

namespace
{
/// Why @p header's image, or one of its tiles (which OpenImageIO decodes
/// into a buffer of the tile's size), is too large to read, or "".
std::string sizeProblem(const slImageHeader& header)
{
  std::string tooMany = slTooManyValues("", header.Width, header.Height, header.Channels);
  if (tooMany.empty())
  {
    tooMany = slTooManyValues("tiles of ", header.TileWidth, header.TileHeight, header.Channels);
  }
  return tooMany.empty() ? "" : "its header declares " + tooMany;
}

/// The one-line reason a read failed: the library's @p error, else what it
/// printed on stderr, else "unknown format".
std::string failureReason(std::string error, const slStderrCapture& printed)
{
  if (error.empty())
  {
    error = printed.Text();
  }
  for (char& c : error)
  {
    c = c == '\n' ? ' ' : c;
  }
  return error.empty() ? "unknown format" : shadelab::printableText(error, 200);
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
  // A file whose length fields reach past its end, and one that is not a
  // regular file, are reported by RequestData; no header is read here, as
  // the library would allocate what the fields claim or read a device for ever.
  std::string ignored;
  const slImageCodec* codec = slLoadImageCodec(ignored);
  if (codec && this->FileName && shadelab::inputFileProblem(this->FileName, "an image file").empty() &&
    slImageFileProblem(this->FileName).empty())
  {
    const slStderrCapture quiet;
    slImageHeader header;
    if (codec->ReadHeader(this->FileName, header, ignored))
    {
      extent[1] = header.Width - 1;
      extent[3] = header.Height - 1;
    }
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  return 1;
}

int slImageReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  output->Initialize();
  const std::string name = this->FileName ? this->FileName : "";
  if (name.empty())
  {
    vtkErrorMacro(<< "(no file name): no image file given");
    return 0;
  }

  // Before any reading: a directory reads as nothing, a device never ends.
  const std::string inputProblem = shadelab::inputFileProblem(name, "an image file");
  if (!inputProblem.empty())
  {
    vtkErrorMacro(<< name << ": " << inputProblem);
    return 0;
  }
  const std::string fileProblem = slImageFileProblem(name);
  if (!fileProblem.empty())
  {
    vtkErrorMacro(<< name << ": cannot read image: " << fileProblem);
    return 0;
  }
  std::string codecProblem;
  const slImageCodec* codec = slLoadImageCodec(codecProblem);
  if (!codec)
  {
    vtkErrorMacro(<< name << ": cannot read image: " << codecProblem);
    return 0;
  }
  slImageHeader header;
  std::string reason;
  vtkSmartPointer<vtkDataArray> scalars;
  {
    // The image libraries' own lines on stderr are held back while they
    // run: the problem is reported once, in the error below, which comes
    // after the capture ends so that it is not held back with them.
    slStderrCapture quiet;
    const bool haveHeader = codec->ReadHeader(name, header, reason);
    const bool asFloat = !(header.EightBit && !this->OutputFloat);
    const std::string tooLarge = haveHeader ? sizeProblem(header) : "";
    if (!tooLarge.empty())
    {
      reason = tooLarge;
    }
    else if (haveHeader)
    {
      if (asFloat)
      {
        scalars = vtkSmartPointer<vtkFloatArray>::New();
      }
      else
      {
        scalars = vtkSmartPointer<vtkUnsignedCharArray>::New();
      }
      scalars->SetName("ImageScalars");
      scalars->SetNumberOfComponents(header.Channels);
      scalars->SetNumberOfTuples(static_cast<vtkIdType>(header.Width) * header.Height);
      if (codec->ReadPixels(name, header, asFloat, scalars->GetVoidPointer(0), reason))
      {
        reason.clear();
      }
      else
      {
        reason = failureReason(reason, quiet);
      }
    }
    else
    {
      reason = failureReason(reason, quiet);
    }
  }
  if (!reason.empty())
  {
    vtkErrorMacro(<< name << ": cannot read image: " << reason);
    return 0;
  }
  output->SetExtent(0, header.Width - 1, 0, header.Height - 1, 0, 0);
  output->GetPointData()->SetScalars(scalars);
  return 1;
}

void slImageReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "OutputFloat: " << this->OutputFloat << "\n";
}
