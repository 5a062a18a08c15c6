#include "BenchTorus.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt64Array.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>
#include <random>

vtkSmartPointer<vtkPolyData> slBenchTorus(long long triangles)
{
  const long long nu = std::max(8LL, static_cast<long long>(std::sqrt(static_cast<double>(triangles))));
  const long long nv = std::max(4LL, triangles / 2 / nu);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(nu * nv);
  for (long long j = 0; j < nv; ++j)
  {
    for (long long i = 0; i < nu; ++i)
    {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      // Ripples with sharp creases: |sin| has a kink at its zeros.
      const double a = 0.3 + 0.02 * std::fabs(std::sin(40 * u));
      points->SetPoint(j * nu + i, (1 + a * std::cos(v)) * std::cos(u), (1 + a * std::cos(v)) * std::sin(u),
        a * std::sin(v));
    }
  }
  vtkNew<vtkTypeInt64Array> offsets, conn;
  offsets->SetNumberOfValues(2 * nu * nv + 1);
  conn->SetNumberOfValues(6 * nu * nv);
  long long c = 0, f = 0;
  for (long long j = 0; j < nv; ++j)
  {
    for (long long i = 0; i < nu; ++i)
    {
      const long long p00 = j * nu + i, p10 = j * nu + (i + 1) % nu, p01 = ((j + 1) % nv) * nu + i,
                      p11 = ((j + 1) % nv) * nu + (i + 1) % nu;
      for (long long id : { p00, p10, p11, p00, p11, p01 })
      {
        conn->SetValue(c++, id);
      }
      offsets->SetValue(f++, c - 6);
      offsets->SetValue(f++, c - 3);
    }
  }
  offsets->SetValue(f, c);
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, conn);
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}

vtkSmartPointer<vtkPolyData> slBenchShuffled(vtkPolyData* mesh, unsigned seed, std::vector<long long>* newId)
{
  std::mt19937_64 rng(seed);
  const long long n = mesh->GetNumberOfPoints(), numTris = mesh->GetNumberOfPolys();
  std::vector<long long> id(static_cast<size_t>(n));
  std::iota(id.begin(), id.end(), 0LL);
  std::shuffle(id.begin(), id.end(), rng);
  auto* in = vtkFloatArray::SafeDownCast(mesh->GetPoints()->GetData());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(n);
  float* to = vtkFloatArray::SafeDownCast(points->GetData())->GetPointer(0);
  for (long long v = 0; v < n; ++v)
  {
    std::copy_n(in->GetPointer(3 * v), 3, to + 3 * id[static_cast<size_t>(v)]);
  }
  std::vector<long long> order(static_cast<size_t>(numTris));
  std::iota(order.begin(), order.end(), 0LL);
  std::shuffle(order.begin(), order.end(), rng);
  const vtkTypeInt64* from = mesh->GetPolys()->GetConnectivityArray64()->GetPointer(0);
  vtkNew<vtkTypeInt64Array> offsets, conn;
  offsets->SetNumberOfValues(numTris + 1);
  conn->SetNumberOfValues(3 * numTris);
  for (long long f = 0; f < numTris; ++f)
  {
    const long long t = order[static_cast<size_t>(f)];
    const long long r = static_cast<long long>(rng() % 3);
    for (long long k = 0; k < 3; ++k)
    {
      conn->SetValue(3 * f + k, id[static_cast<size_t>(from[3 * t + (k + r) % 3])]);
    }
    offsets->SetValue(f, 3 * f);
  }
  offsets->SetValue(numTris, 3 * numTris);
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, conn);
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(polys);
  if (newId)
  {
    *newId = std::move(id);
  }
  return out;
}
