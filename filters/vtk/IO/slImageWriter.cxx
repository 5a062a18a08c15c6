#include "slImageWriter.h"

#include "shadelab/AtomicFile.h"
#include "shadelab/MemoryFile.h"
#include "slFileExtension.h"
#include "slImageCodec.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>


#include <stdexcept>

vtkStandardNewMacro(slImageWriter);

slImageWriter::slImageWriter()
{
  this->SetNumberOfOutputPorts(0);
}

slImageWriter::~slImageWriter()
{
  this->SetFileName(nullptr);
}

const char* slImageWriter::GetSupportedExtensions()
{
  return ".png .jpg .jpeg .exr .hdr .tif .tiff .bmp .tga .ppm";
}

bool slImageWriter::CanWriteFile(const char* fileName)
{
  return slExtensionInList(slLowerExtension(fileName), GetSupportedExtensions());
}

int slImageWriter::FillOutputPortInformation(int, vtkInformation*)
{
  return 1;
}

bool slImageWriter::Write()
{
  this->ErrorMessage.clear();
  this->Modified();
  this->Update();
  return this->ErrorMessage.empty();
}

int slImageWriter::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  vtkImageData* image = vtkImageData::GetData(inputVector[0]);
  return this->WriteImage(image) ? 1 : 0;
}

bool slImageWriter::WriteImage(vtkImageData* image)
{
  const std::string name = this->FileName ? this->FileName : "";
  auto fail = [&](const std::string& problem) {
    this->ErrorMessage = (name.empty() ? std::string("(no file name)") : name) + ": " + problem;
    vtkErrorMacro(<< this->ErrorMessage);
    return false;
  };
  if (name.empty())
  {
    return fail("no output file given");
  }
  const std::string formatProblem = slFormatProblem(name.c_str(), "image", GetSupportedExtensions());
  if (!formatProblem.empty())
  {
    return fail(formatProblem);
  }
  const std::string ext = slLowerExtension(name.c_str());
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  int dims[3] = { 0, 0, 0 };
  if (image)
  {
    image->GetDimensions(dims);
  }
  if (!scalars || dims[0] < 1 || dims[1] < 1 || dims[2] != 1)
  {
    return fail("nothing to write (the input is not a non-empty 2D image with scalars)");
  }
  bool isFloat = false;
  switch (scalars->GetDataType())
  {
    case VTK_UNSIGNED_CHAR:
      break;
    case VTK_FLOAT:
      isFloat = true;
      break;
    default:
      return fail(std::string("unsupported scalar type ") + scalars->GetDataTypeAsString() +
        " (use unsigned char or float)");
  }
  std::string codecProblem;
  const slImageCodec* codec = slLoadImageCodec(codecProblem);
  if (!codec)
  {
    return fail(codecProblem);
  }
  try
  {
    // OpenImageIO's writers do not all report a failed write (PNG reports
    // success on a full disk): they write to memory, ShadeLab to the disk.
    shadelab::MemoryFile memory;
    std::string reason;
    if (!codec->Write(memory.path(), ext.substr(1), dims[0], dims[1], scalars->GetNumberOfComponents(), isFloat,
          scalars->GetVoidPointer(0), reason))
    {
      for (char& c : reason)
      {
        c = c == '\n' ? ' ' : c;
      }
      return fail("cannot write image: " + (reason.empty() ? std::string("the image writer failed") : reason));
    }
    const std::string bytes = memory.contents();
    if (bytes.empty())
    {
      return fail("cannot write image: the image writer produced nothing");
    }
    shadelab::writeFileAtomically(name, bytes);
  }
  catch (const std::runtime_error& e)
  {
    this->ErrorMessage = e.what();
    vtkErrorMacro(<< this->ErrorMessage);
    return false;
  }
  return true;
}

void slImageWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
