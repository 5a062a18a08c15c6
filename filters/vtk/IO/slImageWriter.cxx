#include "slImageWriter.h"
#include "slCoreBoundary.h"

#include "shadelab/AtomicFile.h"
#include "shadelab/MemoryFile.h"
#include "slFileExtension.h"
#include "slImageCodec.h"

#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>



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
  this->Modified();
  return this->GetExecutive()->Update() != 0;
}

int slImageWriter::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  vtkImageData* image = vtkImageData::GetData(inputVector[0]);
  return slRunCore(this, [&] { this->WriteImage(image); }) ? 1 : 0;
}

void slImageWriter::WriteImage(vtkImageData* image)
{
  const std::string name = this->FileName ? this->FileName : "";
  auto fail = [&](const std::string& problem) {
    return shadelab::Error((name.empty() ? std::string("(no file name)") : name) + ": " + problem);
  };
  if (name.empty())
  {
    throw fail("no output file given");
  }
  const std::string formatProblem = slFormatProblem(name.c_str(), "image", GetSupportedExtensions());
  if (!formatProblem.empty())
  {
    throw fail(formatProblem);
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
    throw fail("nothing to write (the input is not a non-empty 2D image with scalars)");
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
      throw fail(std::string("unsupported scalar type ") + scalars->GetDataTypeAsString() +
        " (use unsigned char or float)");
  }
  std::string codecProblem;
  const slImageCodec* codec = slLoadImageCodec(codecProblem);
  if (!codec)
  {
    throw fail(codecProblem);
  }
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
      throw fail("cannot write image: " + (reason.empty() ? std::string("the image writer failed") : reason));
    }
    const std::string bytes = memory.contents();
    if (bytes.empty())
    {
      throw fail("cannot write image: the image writer produced nothing");
    }
    shadelab::writeFileAtomically(name, bytes);
  }
}

void slImageWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
