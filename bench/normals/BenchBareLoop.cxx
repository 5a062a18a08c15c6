#include "BenchBareLoop.h"

#include "slSMPFor.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace
{
/// Triangles [t0, t1) of @p ids into @p sums (zeroed here): the bare loop.
template <typename Id, bool Prefetch>
void sumChunk(const Id* ids, long long t0, long long t1, const float* xyz, float* sums, long long points)
{
  std::fill(sums, sums + 3 * points, 0.0f);
  constexpr long long ahead = 16;
  for (long long t = t0; t < t1; ++t)
  {
    if (Prefetch && t + ahead < t1)
    {
      for (int k = 0; k < 3; ++k)
      {
        const long long a = static_cast<long long>(ids[3 * (t + ahead) + k]);
        __builtin_prefetch(xyz + 3 * a, 0);
        __builtin_prefetch(sums + 3 * a, 1);
      }
    }
    const long long v[3] = { static_cast<long long>(ids[3 * t]), static_cast<long long>(ids[3 * t + 1]),
      static_cast<long long>(ids[3 * t + 2]) };
    const float* p0 = xyz + 3 * v[0];
    const float* p1 = xyz + 3 * v[1];
    const float* p2 = xyz + 3 * v[2];
    const float ax = p1[0] - p0[0], ay = p1[1] - p0[1], az = p1[2] - p0[2];
    const float bx = p2[0] - p0[0], by = p2[1] - p0[1], bz = p2[2] - p0[2];
    const float nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
    for (long long p : v)
    {
      sums[3 * p] += nx;
      sums[3 * p + 1] += ny;
      sums[3 * p + 2] += nz;
    }
  }
}

template <typename Id>
void runChunks(const Id* ids, long long triangles, const float* xyz, std::vector<std::vector<float>>& sums,
  long long points, int chunks, bool prefetch)
{
  // Its threads are spread as slPolyDataNormals' are (slSMPFor.h).
  slSMPFor(0, chunks, 1, [&](vtkIdType kb, vtkIdType ke) {
    for (vtkIdType k = kb; k < ke; ++k)
    {
      const long long t0 = triangles * k / chunks, t1 = triangles * (k + 1) / chunks;
      float* s = sums[static_cast<size_t>(k)].data();
      if (prefetch)
      {
        sumChunk<Id, true>(ids, t0, t1, xyz, s, points);
      }
      else
      {
        sumChunk<Id, false>(ids, t0, t1, xyz, s, points);
      }
    }
  });
}
} // namespace

slBenchBareLoop::slBenchBareLoop(vtkPolyData* mesh, int chunks, bool prefetch)
  : Mesh(mesh)
  , Prefetch(prefetch)
  , Sums(static_cast<size_t>(std::max(chunks, 1)))
{
  vtkCellArray* cells = mesh->GetPolys();
  if (!vtkFloatArray::SafeDownCast(mesh->GetPoints()->GetData()) ||
    cells->GetNumberOfConnectivityIds() != 3 * cells->GetNumberOfCells() ||
    mesh->GetNumberOfCells() != cells->GetNumberOfCells())
  {
    std::fprintf(stderr, "bare loop: the mesh is not float points and triangles only\n");
    std::exit(2);
  }
  for (std::vector<float>& s : this->Sums)
  {
    s.resize(static_cast<size_t>(3 * mesh->GetNumberOfPoints()));
  }
}

void slBenchBareLoop::Run(int chunks)
{
  chunks = std::min(std::max(chunks, 1), static_cast<int>(this->Sums.size()));
  this->LastChunks = chunks;
  vtkCellArray* cells = this->Mesh->GetPolys();
  const float* xyz = vtkFloatArray::SafeDownCast(this->Mesh->GetPoints()->GetData())->GetPointer(0);
  const long long points = this->Mesh->GetNumberOfPoints();
  const long long triangles = cells->GetNumberOfCells();
  if (cells->IsStorage64Bit())
  {
    runChunks(
      cells->GetConnectivityArray64()->GetPointer(0), triangles, xyz, this->Sums, points, chunks, this->Prefetch);
  }
  else
  {
    runChunks(
      cells->GetConnectivityArray32()->GetPointer(0), triangles, xyz, this->Sums, points, chunks, this->Prefetch);
  }
}

double slBenchBareLoop::LargestAngleTo(vtkDataArray* normals) const
{
  double largest = 0;
  const vtkIdType points = this->Mesh->GetNumberOfPoints();
  for (vtkIdType p = 0; p < points; ++p)
  {
    double s[3] = { 0, 0, 0 };
    for (int k = 0; k < this->LastChunks; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        s[c] += this->Sums[static_cast<size_t>(k)][static_cast<size_t>(3 * p + c)];
      }
    }
    double n[3];
    normals->GetTuple(p, n);
    const double cx = s[1] * n[2] - s[2] * n[1], cy = s[2] * n[0] - s[0] * n[2], cz = s[0] * n[1] - s[1] * n[0];
    const double sine = std::sqrt(cx * cx + cy * cy + cz * cz), cosine = s[0] * n[0] + s[1] * n[1] + s[2] * n[2];
    if (s[0] != 0 || s[1] != 0 || s[2] != 0)
    {
      largest = std::max(largest, std::atan2(sine, cosine) * 180.0 / 3.14159265358979323846);
    }
  }
  return largest;
}
