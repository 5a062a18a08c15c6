#include "slNormalsVTKBridge.h"
#include "slAtomicMinimum.h"

#include <vtkFloatArray.h>
#include <vtkPoints.h>
#include <vtkSMPTools.h>

#include <atomic>
#include <cmath>

slnormals::Parallel slSMPParallel()
{
  slnormals::Parallel p;
  p.threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  p.forRange = [](int64_t begin, int64_t end, int64_t grain, const slnormals::Parallel::Body& body) {
    vtkSMPTools::For(static_cast<vtkIdType>(begin), static_cast<vtkIdType>(end), static_cast<vtkIdType>(grain),
      [&body](vtkIdType b, vtkIdType e) { body(b, e); });
  };
  return p;
}

vtkIdType slFirstNonFinitePoint(vtkPoints* points)
{
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  std::atomic<vtkIdType> first{ n };
  vtkDataArray* data = n ? points->GetData() : nullptr;
  const float* f = vtkFloatArray::SafeDownCast(data) ? vtkFloatArray::SafeDownCast(data)->GetPointer(0) : nullptr;
  vtkSMPTools::For(0, n, 65536, [&](vtkIdType b, vtkIdType e) {
    for (vtkIdType i = b; i < e; ++i)
    {
      double p[3];
      if (f)
      {
        p[0] = f[3 * i], p[1] = f[3 * i + 1], p[2] = f[3 * i + 2];
      }
      else
      {
        data->GetTuple(i, p);
      }
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      {
        slAtomicMinimum(first, i);
        return;
      }
    }
  });
  return first.load() < n ? first.load() : -1;
}
