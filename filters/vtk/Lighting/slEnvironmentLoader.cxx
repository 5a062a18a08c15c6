#include "slEnvironmentLoader.h"

#include "slImageReader.h"
#include "slUpdateOrThrow.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <vector>

namespace shadelab
{

void environmentFromImage(vtkImageData* image, const std::string& name, EnvironmentMap& out)
{
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  int dims[3] = { 0, 0, 0 };
  if (image)
  {
    image->GetDimensions(dims);
  }
  if (!scalars || dims[0] < 1 || dims[1] < 1)
  {
    throw Error(name + ": environment map is empty");
  }
  if (dims[2] != 1)
  {
    throw Error(name + ": environment map is a 3D image; it must be a 2D equirectangular image");
  }
  if (scalars->GetNumberOfComponents() < 3)
  {
    throw Error(name + ": environment map has " + std::to_string(scalars->GetNumberOfComponents()) +
      " channel(s); it needs RGB");
  }
  const bool bytes = scalars->GetDataType() == VTK_UNSIGNED_CHAR;
  std::vector<float> rgb(static_cast<size_t>(3) * dims[0] * dims[1]);
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(dims[0]) * dims[1]; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = scalars->GetComponent(i, c);
      rgb[static_cast<size_t>(3 * i + c)] = static_cast<float>(bytes ? v / 255.0 : v);
    }
  }
  out.set(dims[0], dims[1], std::move(rgb), name);
}

void environmentFromFile(const std::string& fileName, EnvironmentMap& out)
{
  vtkNew<slImageReader> reader;
  reader->SetFileName(fileName.c_str());
  reader->OutputFloatOn();
  slUpdateOrThrow(reader);
  environmentFromImage(reader->GetOutput(), fileName, out);
}

} // namespace shadelab
