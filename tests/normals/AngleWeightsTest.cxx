// Angle weighting (the default) against an independent computation: corner
// angles by std::acos in double, Newell normals, plain sums. The filter's
// corner angles come from a polynomial atan2 in vectorised blocks; its
// normals must agree to < 1e-3 degrees, with float and with double points,
// on every path that weighs corners: no splitting, splitting, welding.
#include "NormalsTestMeshes.h"

#include "slPolyDataNormals.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace
{
using normalstest::Vec;

Vec sub(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

Vec cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

double dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// Angle-weighted vertex normals of @p mesh's polygons, by the textbook:
/// Σ acos(e1·e2 / |e1||e2|) × unit Newell normal, normalised ((0,0,0) if none).
std::vector<Vec> acosReference(vtkPolyData* mesh)
{
  std::vector<Vec> sum(static_cast<size_t>(mesh->GetNumberOfPoints()), Vec{ 0, 0, 0 });
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetPolys()->GetNumberOfCells(); ++c)
  {
    mesh->GetPolys()->GetCellAtId(c, ids);
    const vtkIdType n = ids->GetNumberOfIds();
    std::vector<Vec> p(static_cast<size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      mesh->GetPoint(ids->GetId(i), p[static_cast<size_t>(i)].data());
    }
    Vec nv{ 0, 0, 0 };
    for (vtkIdType i = 1; i + 1 < n; ++i)
    {
      const Vec t = cross(sub(p[static_cast<size_t>(i)], p[0]), sub(p[static_cast<size_t>(i + 1)], p[0]));
      nv = { nv[0] + t[0], nv[1] + t[1], nv[2] + t[2] };
    }
    if (!(dot(nv, nv) > 0))
    {
      continue;
    }
    const Vec u = normalstest::normalized(nv);
    for (vtkIdType i = 0; i < n; ++i)
    {
      const Vec& q = p[static_cast<size_t>(i)];
      const Vec e1 = sub(p[static_cast<size_t>((i + 1) % n)], q), e2 = sub(p[static_cast<size_t>((i + n - 1) % n)], q);
      const double l = std::sqrt(dot(e1, e1) * dot(e2, e2));
      const double angle = l > 0 ? std::acos(std::max(-1.0, std::min(1.0, dot(e1, e2) / l))) : 0.0;
      Vec& s = sum[static_cast<size_t>(ids->GetId(i))];
      s = { s[0] + angle * u[0], s[1] + angle * u[1], s[2] + angle * u[2] };
    }
  }
  for (Vec& s : sum)
  {
    s = dot(s, s) > 0 ? normalstest::normalized(s) : Vec{ 0, 0, 0 };
  }
  return sum;
}

/// @p mesh with float points (the filter's float instantiation).
vtkSmartPointer<vtkPolyData> withFloatPoints(vtkPolyData* mesh)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(mesh);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->DeepCopy(mesh->GetPoints());
  out->SetPoints(points);
  return out;
}

/// Every polygon with its own copies of its points (a triangle soup), so
/// that only welding makes it a surface again.
vtkSmartPointer<vtkPolyData> soup(vtkPolyData* mesh)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(mesh->GetPoints()->GetDataType());
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetPolys()->GetNumberOfCells(); ++c)
  {
    mesh->GetPolys()->GetCellAtId(c, ids);
    cells->InsertNextCell(ids->GetNumberOfIds());
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
    {
      cells->InsertCellPoint(points->InsertNextPoint(mesh->GetPoint(ids->GetId(i))));
    }
  }
  out->SetPoints(points);
  out->SetPolys(cells);
  return out;
}

/// A jittered height field of n x n cells, each a quad when (i + j) %
/// @p quadEvery is 0 and a triangle pair otherwise: polygons that are not
/// triangles interrupt the runs of triangles the filter weighs in blocks
/// (64 at a time; a run of 64 is filled in one go).
vtkSmartPointer<vtkPolyData> mixedPolygons(int n, int quadEvery)
{
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      const double x = i + jitter(rng), y = j + jitter(rng);
      points->InsertNextPoint(x, y, 2 * std::sin(0.3 * x) * std::cos(0.2 * y));
    }
  }
  vtkNew<vtkCellArray> cells;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const vtkIdType a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      if ((i + j) % quadEvery == 0)
      {
        const vtkIdType quad[4] = { a, b, c, d };
        cells->InsertNextCell(4, quad);
        continue;
      }
      const vtkIdType t0[3] = { a, b, c }, t1[3] = { a, c, d };
      cells->InsertNextCell(3, t0);
      cells->InsertNextCell(3, t1);
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(cells);
  return mesh;
}

vtkSmartPointer<vtkPolyData> angleNormals(vtkPolyData* mesh, bool split, bool weld)
{
  vtkNew<slPolyDataNormals> f;
  f->SetInputData(mesh);
  f->SetSplitting(split);
  f->SetFeatureAngle(180); // splitting runs, but every smooth group is the whole fan
  f->ConsistencyOff();
  f->SetWeldCoincidentPoints(weld);
  f->Update();
  vtkSmartPointer<vtkPolyData> out = f->GetOutput();
  return out;
}

/// Largest angle (degrees) between @p out's normals and the reference normal
/// of the input point at the same position.
double maxDegreesOff(vtkPolyData* out, vtkPolyData* reference, const std::vector<Vec>& expected)
{
  std::map<Vec, Vec> byPosition;
  for (vtkIdType i = 0; i < reference->GetNumberOfPoints(); ++i)
  {
    Vec p;
    reference->GetPoint(i, p.data());
    byPosition[p] = expected[static_cast<size_t>(i)];
  }
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  double worst = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    Vec p, n;
    out->GetPoint(i, p.data());
    normals->GetTuple(i, n.data());
    const auto it = byPosition.find(p);
    if (it == byPosition.end())
    {
      ADD_FAILURE() << "output point " << i << " is not an input point";
      return 180;
    }
    // A NaN or zero normal is as wrong as can be (std::max would drop a NaN).
    const double angle = normalstest::angleDegrees(n.data(), it->second.data());
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    worst = std::abs(length - 1.0) < 1e-5 && angle <= 180.0 ? std::max(worst, angle) : 180.0;
  }
  return worst;
}
} // namespace

TEST(NormalsAngleWeights, AgreeWithAcosOnIrregularMeshesOnEveryPath)
{
  const std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> meshes = {
    { "irregular sphere", normalstest::irregularEllipsoid({ 1, 1, 1 }, 7) },
    { "coarse irregular ellipsoid", normalstest::irregularEllipsoid({ 1.5, 1, 0.6 }, 13, 2) },
    { "irregular torus", normalstest::irregularTorus(1.0, 0.35, 64, 24, 5) },
    { "quads and triangles", mixedPolygons(24, 5) },
    // About 2 x 190^2 polygons, more than one chunk's worth (the filter cuts meshes
    // of 65536 polygons or more into chunks): runs of 100 to 200 triangles
    // between quads, so that blocks filled in one go, blocks filled triangle
    // by triangle and chunk borders all fall inside runs.
    { "long runs of triangles", mixedPolygons(190, 97) },
  };
  for (const auto& named : meshes)
  {
    for (const bool asFloat : { false, true })
    {
      vtkSmartPointer<vtkPolyData> mesh = asFloat ? withFloatPoints(named.second) : named.second;
      const std::vector<Vec> expected = acosReference(mesh);
      const std::string what = named.first + (asFloat ? ", float points" : ", double points");
      EXPECT_LT(maxDegreesOff(angleNormals(mesh, false, false), mesh, expected), 1e-3) << what << ", no split";
      EXPECT_LT(maxDegreesOff(angleNormals(mesh, true, false), mesh, expected), 1e-3) << what << ", split";
      EXPECT_LT(maxDegreesOff(angleNormals(soup(mesh), true, true), mesh, expected), 1e-3)
        << what << ", welded soup";
    }
  }
}

// GCC 12.2 at -O2 once compiled the block kernel's scatter away for float
// points (slTriangleBlock.h): a mesh smaller than one block, with a
// degenerate triangle and an unused point, came out all zero.
TEST(NormalsAngleWeights, TinyFloatMeshIsNotZero)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  for (const Vec& p : { Vec{ 0, 0, 0 }, Vec{ 1, 0, 0 }, Vec{ 0, 1, 0 }, Vec{ 1, 0, 0 }, Vec{ 5, 5, 5 } })
  {
    points->InsertNextPoint(p.data());
  }
  vtkNew<vtkCellArray> cells;
  const vtkIdType t0[3] = { 0, 1, 2 }, t1[3] = { 1, 3, 2 };
  cells->InsertNextCell(3, t0);
  cells->InsertNextCell(3, t1);
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(cells);
  for (int w = 0; w < 4; ++w)
  {
    vtkNew<slPolyDataNormals> f;
    f->SetInputData(mesh);
    f->SetWeighting(w);
    f->SplittingOff();
    f->ConsistencyOff();
    f->Update();
    vtkDataArray* n = f->GetOutput()->GetPointData()->GetNormals();
    for (vtkIdType i = 0; i < 3; ++i)
    {
      EXPECT_EQ(n->GetComponent(i, 2), 1.0) << "weighting " << w << " point " << i;
    }
    EXPECT_EQ(n->GetComponent(4, 2), 0.0) << "weighting " << w << ", the unused point";
  }
}
