#ifndef shadelab_tests_NormalsTestMeshes_h
#define shadelab_tests_NormalsTestMeshes_h
// Surfaces with analytic normals, irregularly tessellated, for the normals
// tests. Every vertex lies exactly on the surface; "AnalyticNormals" holds
// the exact unit normal there (computed from the surface's equation).

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace normalstest
{
using Vec = std::array<double, 3>;

inline Vec normalized(const Vec& v)
{
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return { v[0] / l, v[1] / l, v[2] / l };
}

/// Degrees between two vectors (std::acos on the normalised dot product).
inline double angleDegrees(const double* a, const double* b)
{
  const Vec u = normalized({ a[0], a[1], a[2] }), v = normalized({ b[0], b[1], b[2] });
  double d = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  d = d > 1 ? 1 : (d < -1 ? -1 : d);
  // atan2 form: accurate for tiny angles, where acos is not.
  const Vec c = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
  return std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), d) * 180.0 / M_PI;
}

/// Unit-sphere icosahedron subdivided @p levels times.
inline void icosphere(int levels, std::vector<Vec>& pts, std::vector<std::array<vtkIdType, 3>>& tris)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  pts = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 }, { 0, -1, t }, { 0, 1, t }, { 0, -1, -t },
    { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 }, { -t, 0, 1 } };
  for (Vec& p : pts)
  {
    p = normalized(p);
  }
  tris = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 }, { 1, 5, 9 }, { 5, 11, 4 },
    { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 },
    { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };
  for (int l = 0; l < levels; ++l)
  {
    std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> mid;
    auto middle = [&](vtkIdType a, vtkIdType b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if (it != mid.end())
      {
        return it->second;
      }
      const Vec& p = pts[a];
      const Vec& q = pts[b];
      pts.push_back(normalized({ p[0] + q[0], p[1] + q[1], p[2] + q[2] }));
      return mid[key] = static_cast<vtkIdType>(pts.size() - 1);
    };
    std::vector<std::array<vtkIdType, 3>> next;
    for (const auto& tr : tris)
    {
      const vtkIdType a = middle(tr[0], tr[1]), b = middle(tr[1], tr[2]), c = middle(tr[2], tr[0]);
      next.push_back({ tr[0], a, c });
      next.push_back({ tr[1], b, a });
      next.push_back({ tr[2], c, b });
      next.push_back({ a, b, c });
    }
    tris = next;
  }
}

inline vtkSmartPointer<vtkPolyData> makePolyData(const std::vector<Vec>& pts,
  const std::vector<std::array<vtkIdType, 3>>& tris, const std::vector<Vec>& normals)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> analytic;
  analytic->SetName("AnalyticNormals");
  analytic->SetNumberOfComponents(3);
  for (size_t i = 0; i < pts.size(); ++i)
  {
    points->InsertNextPoint(pts[i].data());
    analytic->InsertNextTuple(normals[i].data());
  }
  vtkNew<vtkCellArray> cells;
  for (const auto& t : tris)
  {
    cells->InsertNextCell(3, t.data());
  }
  mesh->SetPoints(points);
  mesh->SetPolys(cells);
  mesh->GetPointData()->AddArray(analytic);
  return mesh;
}

/// A sphere (radii 1, 1, 1) or ellipsoid (radii @p r) from an icosphere
/// whose vertices are moved along the surface by random amounts and crowded
/// towards +z, so triangle sizes and shapes vary widely.
inline vtkSmartPointer<vtkPolyData> irregularEllipsoid(const Vec& r, unsigned seed, int levels = 4)
{
  std::vector<Vec> pts;
  std::vector<std::array<vtkIdType, 3>> tris;
  icosphere(levels, pts, tris);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.35, 0.35);
  const double edge = 1.1 / (1 << levels);
  std::vector<Vec> normals(pts.size());
  for (size_t i = 0; i < pts.size(); ++i)
  {
    Vec p = pts[i];
    p = normalized({ p[0] + jitter(rng) * edge, p[1] + jitter(rng) * edge, p[2] + jitter(rng) * edge + 0.5 });
    pts[i] = { r[0] * p[0], r[1] * p[1], r[2] * p[2] };
    // Gradient of (x/a)^2 + (y/b)^2 + (z/c)^2 at the scaled point.
    normals[i] = normalized({ p[0] / r[0], p[1] / r[1], p[2] / r[2] });
  }
  return makePolyData(pts, tris, normals);
}

/// A torus (radii R, a) from a jittered u x v grid with random diagonals.
inline vtkSmartPointer<vtkPolyData> irregularTorus(double R, double a, int nu, int nv, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::bernoulli_distribution coin(0.5);
  std::vector<Vec> pts, normals;
  for (int j = 0; j < nv; ++j)
  {
    for (int i = 0; i < nu; ++i)
    {
      const double u = 2 * M_PI * (i + jitter(rng)) / nu, v = 2 * M_PI * (j + jitter(rng)) / nv;
      pts.push_back({ (R + a * std::cos(v)) * std::cos(u), (R + a * std::cos(v)) * std::sin(u), a * std::sin(v) });
      normals.push_back({ std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v) });
    }
  }
  std::vector<std::array<vtkIdType, 3>> tris;
  auto id = [&](int i, int j) { return static_cast<vtkIdType>((j % nv) * nu + (i % nu)); };
  for (int j = 0; j < nv; ++j)
  {
    for (int i = 0; i < nu; ++i)
    {
      const vtkIdType p00 = id(i, j), p10 = id(i + 1, j), p01 = id(i, j + 1), p11 = id(i + 1, j + 1);
      if (coin(rng))
      {
        tris.push_back({ p00, p10, p11 });
        tris.push_back({ p00, p11, p01 });
      }
      else
      {
        tris.push_back({ p00, p10, p01 });
        tris.push_back({ p10, p11, p01 });
      }
    }
  }
  return makePolyData(pts, tris, normals);
}

} // namespace normalstest

#endif
