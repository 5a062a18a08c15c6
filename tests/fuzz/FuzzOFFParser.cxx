// The OFF parser on any bytes: a mesh whose faces name existing points, or a
// problem.
#include "slOFFParser.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  vtkNew<vtkPolyData> mesh;
  bool parsed = true;
  try
  {
    slParseOFF(in, "fuzz.off", mesh);
  }
  catch (const shadelab::Error&)
  {
    parsed = false;
  }
  if (parsed)
  {
    vtkIdType n;
    const vtkIdType* ids;
    auto polys = mesh->GetPolys();
    for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
    {
      for (vtkIdType k = 0; k < n; ++k)
      {
        if (ids[k] < 0 || ids[k] >= mesh->GetNumberOfPoints())
        {
          std::abort();
        }
      }
    }
  }
  return 0;
}
