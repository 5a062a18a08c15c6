#include "slNormalsVTKBridge.h"
#include "shadelab/slAtomicMinimum.h"

#include <vtkFloatArray.h>
#include <vtkPoints.h>
#include <vtkSMPTools.h>

#include <vtkSMPThreadLocal.h>

#include <algorithm>
#include <array>
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

vtkIdType slFirstNonFinitePoint(vtkPoints* points, double* largestSide)
{
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  std::atomic<vtkIdType> first{ n };
  vtkDataArray* data = n ? points->GetData() : nullptr;
  const float* f = vtkFloatArray::SafeDownCast(data) ? vtkFloatArray::SafeDownCast(data)->GetPointer(0) : nullptr;
  // Each thread's bounding box, from the same pass (the points are read once).
  vtkSMPThreadLocal<std::array<double, 6>> boxes(
    std::array<double, 6>{ { HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL } });
  vtkSMPTools::For(0, n, 65536, [&](vtkIdType b, vtkIdType e) {
    std::array<double, 6>& box = boxes.Local();
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
      for (int c = 0; c < 3; ++c)
      {
        box[2 * c] = std::min(box[2 * c], p[c]);
        box[2 * c + 1] = std::max(box[2 * c + 1], p[c]);
      }
    }
  });
  if (largestSide)
  {
    std::array<double, 6> all{ { HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL } };
    for (const std::array<double, 6>& box : boxes)
    {
      for (int c = 0; c < 3; ++c)
      {
        all[2 * c] = std::min(all[2 * c], box[2 * c]);
        all[2 * c + 1] = std::max(all[2 * c + 1], box[2 * c + 1]);
      }
    }
    *largestSide = std::max({ all[1] - all[0], all[3] - all[2], all[5] - all[4], 0.0 });
  }
  return first.load() < n ? first.load() : -1;
}
