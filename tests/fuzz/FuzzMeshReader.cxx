// slMeshReader on any bytes as a file of one extension (SL_FUZZ_EXTENSION):
// either an error message and an empty output, or a mesh that every
// ShadeLab filter may follow (finite points, cells naming existing points).
#include "FuzzInputFile.h"
#include "FuzzToolOutput.h"

#include "slConnectivityCheck.h"
#include "slMeshReader.h"
#include "slUpdateOrThrow.h"

#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <cmath>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string path = fuzzInputFile(data, size, SL_FUZZ_EXTENSION);
  vtkNew<slMeshReader> reader;
  reader->SetFileName(path.c_str());
  bool failed = false;
  try
  {
    slUpdateOrThrow(reader);
  }
  catch (const shadelab::Error&)
  {
    failed = true;
  }
  vtkPolyData* mesh = reader->GetOutput();
  if (failed != (mesh->GetNumberOfPoints() == 0) || !slConnectivityProblem(mesh).empty())
  {
    std::abort();
  }
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    if (!std::isfinite(p[0] + p[1] + p[2]))
    {
      std::abort();
    }
  }
  return 0;
}
