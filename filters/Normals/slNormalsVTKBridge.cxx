#include "slNormalsVTKBridge.h"
#include "slAtomicMinimum.h"

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
    if (f)
    {
      // Float points: one branch-free pass over the range as a flat array,
      // four points (12 values) at a time so that it vectorises; lane k
      // holds component k % 3. Float min and max are exact, so the box is
      // the same as in double.
      float lo[12], hi[12];
      std::fill(lo, lo + 12, HUGE_VALF);
      std::fill(hi, hi + 12, -HUGE_VALF);
      unsigned bad = 0;
      const float* p = f + 3 * b;
      const vtkIdType values = 3 * (e - b);
      vtkIdType i = 0;
      for (; i + 12 <= values; i += 12)
      {
        for (int k = 0; k < 12; ++k)
        {
          const float x = p[i + k];
          bad |= !(x - x == 0.0f); // NaN and infinities only
          lo[k] = x < lo[k] ? x : lo[k];
          hi[k] = x > hi[k] ? x : hi[k];
        }
      }
      for (; i < values; ++i)
      {
        const float x = p[i];
        const int k = static_cast<int>(i % 3);
        bad |= !(x - x == 0.0f);
        lo[k] = x < lo[k] ? x : lo[k];
        hi[k] = x > hi[k] ? x : hi[k];
      }
      if (bad)
      {
        for (vtkIdType v = b; v < e; ++v)
        {
          if (!std::isfinite(f[3 * v]) || !std::isfinite(f[3 * v + 1]) || !std::isfinite(f[3 * v + 2]))
          {
            slAtomicMinimum(first, v);
            return;
          }
        }
      }
      for (int k = 0; k < 12; ++k)
      {
        box[2 * (k % 3)] = std::min(box[2 * (k % 3)], static_cast<double>(lo[k]));
        box[2 * (k % 3) + 1] = std::max(box[2 * (k % 3) + 1], static_cast<double>(hi[k]));
      }
      return;
    }
    for (vtkIdType i = b; i < e; ++i)
    {
      double p[3];
      data->GetTuple(i, p);
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
