// slPolyDataTangents against analytic tangents (planes, a cylinder), an
// independent per-triangle computation on spot.obj, and bad input.
#include "slMeshReader.h"
#include "slPolyDataTangents.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>

namespace
{
using Vec = std::array<double, 3>;

/// An nx x ny grid of quads; position(i, j), uv(i, j), normal(i, j) given.
vtkSmartPointer<vtkPolyData> grid(int nx, int ny, const std::function<Vec(int, int)>& position,
  const std::function<std::array<double, 2>(int, int)>& uv, const std::function<Vec(int, int)>& normal)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> tc, nn;
  tc->SetName("UV");
  tc->SetNumberOfComponents(2);
  nn->SetName("Normals");
  nn->SetNumberOfComponents(3);
  for (int j = 0; j <= ny; ++j)
  {
    for (int i = 0; i <= nx; ++i)
    {
      points->InsertNextPoint(position(i, j).data());
      tc->InsertNextTuple(uv(i, j).data());
      nn->InsertNextTuple(normal(i, j).data());
    }
  }
  vtkNew<vtkCellArray> quads;
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const vtkIdType a = j * (nx + 1) + i;
      const vtkIdType q[] = { a, a + 1, a + nx + 2, a + nx + 1 };
      quads->InsertNextCell(4, q);
    }
  }
  auto m = vtkSmartPointer<vtkPolyData>::New();
  m->SetPoints(points);
  m->SetPolys(quads);
  m->GetPointData()->SetTCoords(tc);
  m->GetPointData()->SetNormals(nn);
  return m;
}

struct Result
{
  vtkSmartPointer<vtkPolyData> out;
  vtkIdType split = 0;
  int errors = 0;
};

Result tangentsOf(vtkPolyData* m)
{
  vtkNew<slPolyDataTangents> f;
  f->SetInputData(m);
  Result r;
  vtkNew<vtkCallbackCommand> count;
  count->SetClientData(&r.errors);
  count->SetCallback([](vtkObject*, unsigned long, void* n, void*) { ++*static_cast<int*>(n); });
  f->AddObserver(vtkCommand::ErrorEvent, count);
  f->Update();
  r.out = f->GetOutput();
  r.split = f->GetNumberOfSplitPoints();
  return r;
}

void expectTangents(vtkPolyData* out, const std::function<std::array<double, 4>(const double*)>& expected)
{
  vtkDataArray* t = out->GetPointData()->GetArray("Tangents");
  ASSERT_NE(t, nullptr);
  ASSERT_EQ(t->GetNumberOfComponents(), 4);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3], v[4];
    out->GetPoint(i, p);
    t->GetTuple(i, v);
    const std::array<double, 4> e = expected(p);
    for (int k = 0; k < 4; ++k)
    {
      EXPECT_NEAR(v[k], e[k], 1e-5) << "point " << i << " component " << k;
    }
  }
}
} // namespace

TEST(Tangents, PlaneWithRotatedAndMirroredUVs)
{
  const Vec up = { 0, 0, 1 };
  for (double alpha : { 0.0, 0.7, -2.0 })
  {
    const double c = std::cos(alpha), s = std::sin(alpha);
    // u = x cos a + y sin a: the direction of increasing u is (cos a, sin a, 0).
    Result r = tangentsOf(grid(
      4, 3, [](int i, int j) { return Vec{ 0.5 * i, 0.5 * j, 0 }; },
      [&](int i, int j) { return std::array<double, 2>{ c * 0.5 * i + s * 0.5 * j, -s * 0.5 * i + c * 0.5 * j }; },
      [&](int, int) { return up; }));
    expectTangents(r.out, [&](const double*) { return std::array<double, 4>{ c, s, 0, 1 }; });
    // Mirrored: u = -x. T = (-1, 0, 0) and B = w N x T = (0, 1, 0) needs w = -1.
    Result m = tangentsOf(grid(
      4, 3, [](int i, int j) { return Vec{ 0.5 * i, 0.5 * j, 0 }; },
      [](int i, int j) { return std::array<double, 2>{ -0.5 * i, 0.5 * j }; }, [&](int, int) { return up; }));
    expectTangents(m.out, [](const double*) { return std::array<double, 4>{ -1, 0, 0, -1 }; });
    EXPECT_EQ(m.split, 0);
  }
}

TEST(Tangents, CylinderTangentsFollowTheCircle)
{
  const int n = 24;
  // The u seam: column n repeats column 0's positions with u = 1 instead of 0.
  Result r = tangentsOf(grid(
    n, 4,
    [&](int i, int j) {
      const double t = 2 * M_PI * i / n;
      return Vec{ std::cos(t), std::sin(t), 0.25 * j };
    },
    [&](int i, int j) { return std::array<double, 2>{ static_cast<double>(i) / n, 0.25 * j }; },
    [&](int i, int) {
      const double t = 2 * M_PI * i / n;
      return Vec{ std::cos(t), std::sin(t), 0 };
    }));
  // dP/du = (-sin t, cos t, 0); N x T = (0, 0, 1) = dP/dv, so w = +1.
  expectTangents(r.out, [](const double* p) {
    const double t = std::atan2(p[1], p[0]);
    return std::array<double, 4>{ -std::sin(t), std::cos(t), 0, 1 };
  });
}

TEST(Tangents, MirrorSeamPointsAreDuplicated)
{
  // u = |x - 2| on x in [0, 4]: mirrored left of x = 2, whose 4 points split.
  const Vec up = { 0, 0, 1 };
  Result r = tangentsOf(grid(
    4, 3, [](int i, int j) { return Vec{ 1.0 * i, 1.0 * j, 0 }; },
    [](int i, int j) { return std::array<double, 2>{ std::fabs(i - 2.0), 1.0 * j }; }, [&](int, int) { return up; }));
  EXPECT_EQ(r.split, 4);
  EXPECT_EQ(r.out->GetNumberOfPoints(), 20 + 4);
  // Each polygon's corners carry the frame of its own side.
  vtkDataArray* t = r.out->GetPointData()->GetArray("Tangents");
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < r.out->GetNumberOfPolys(); ++c)
  {
    r.out->GetPolys()->GetCellAtId(c, ids);
    double centre[3] = { 0, 0, 0 };
    for (vtkIdType k = 0; k < 4; ++k)
    {
      double p[3];
      r.out->GetPoint(ids->GetId(k), p);
      centre[0] += p[0] / 4;
    }
    const double side = centre[0] > 2 ? 1 : -1;
    for (vtkIdType k = 0; k < 4; ++k)
    {
      double v[4];
      t->GetTuple(ids->GetId(k), v);
      EXPECT_NEAR(v[0], side, 1e-6);
      EXPECT_EQ(v[3], side);
    }
  }
}

TEST(Tangents, SpotAgreesWithAnIndependentPerTriangleComputation)
{
  vtkNew<slMeshReader> reader;
  reader->SetFileName(SHADELAB_DATA_DIR "/meshes/spot.obj");
  reader->Update();
  Result r = tangentsOf(reader->GetOutput());
  ASSERT_EQ(r.errors, 0);
  vtkPolyData* out = r.out;
  vtkDataArray* t = out->GetPointData()->GetArray("Tangents");
  vtkDataArray* n = out->GetPointData()->GetNormals();
  vtkDataArray* uv = out->GetPointData()->GetTCoords();
  ASSERT_NE(t, nullptr);
  ASSERT_NE(n, nullptr);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double v[4], nv[3];
    t->GetTuple(i, v);
    n->GetTuple(i, nv);
    EXPECT_NEAR(v[0] * v[0] + v[1] * v[1] + v[2] * v[2], 1.0, 1e-5);
    EXPECT_NEAR(v[0] * nv[0] + v[1] * nv[1] + v[2] * nv[2], 0.0, 1e-5);
    EXPECT_TRUE(v[3] == 1.0 || v[3] == -1.0);
  }
  // Per triangle, by Lengyel's formula: dP/du and the sign of the UV area.
  long corners = 0, agree = 0, signOk = 0;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < out->GetNumberOfPolys(); ++c)
  {
    out->GetPolys()->GetCellAtId(c, ids);
    ASSERT_EQ(ids->GetNumberOfIds(), 3);
    double p[3][3], q[3][2];
    for (int k = 0; k < 3; ++k)
    {
      out->GetPoint(ids->GetId(k), p[k]);
      uv->GetTuple(ids->GetId(k), q[k]);
    }
    const double du1 = q[1][0] - q[0][0], dv1 = q[1][1] - q[0][1], du2 = q[2][0] - q[0][0], dv2 = q[2][1] - q[0][1];
    const double area = du1 * dv2 - du2 * dv1;
    if (std::fabs(area) < 1e-12)
    {
      continue;
    }
    double dpdu[3];
    for (int a = 0; a < 3; ++a)
    {
      dpdu[a] = ((p[1][a] - p[0][a]) * dv2 - (p[2][a] - p[0][a]) * dv1) / area;
    }
    for (int k = 0; k < 3; ++k)
    {
      double v[4];
      t->GetTuple(ids->GetId(k), v);
      ++corners;
      signOk += v[3] == (area > 0 ? 1.0 : -1.0);
      const double dot = v[0] * dpdu[0] + v[1] * dpdu[1] + v[2] * dpdu[2];
      const double len = std::sqrt(dpdu[0] * dpdu[0] + dpdu[1] * dpdu[1] + dpdu[2] * dpdu[2]);
      agree += dot > std::cos(M_PI / 4) * len; // within 45 degrees
    }
  }
  EXPECT_GT(corners, 15000);
  EXPECT_EQ(signOk, corners);
  EXPECT_GT(static_cast<double>(agree) / corners, 0.99);
}

TEST(Tangents, NoUVsOrNaNGiveAnErrorAndAnEmptyOutput)
{
  vtkNew<slMeshReader> reader;
  reader->SetFileName(SHADELAB_DATA_DIR "/meshes/fandisk.obj"); // no UVs
  reader->Update();
  Result r = tangentsOf(reader->GetOutput());
  EXPECT_EQ(r.errors, 1);
  EXPECT_EQ(r.out->GetNumberOfPoints(), 0);

  const Vec up = { 0, 0, 1 };
  auto plane = grid(
    2, 2, [](int i, int j) { return Vec{ 1.0 * i, 1.0 * j, 0 }; },
    [](int i, int j) { return std::array<double, 2>{ 1.0 * i, 1.0 * j }; }, [&](int, int) { return up; });
  plane->GetPoints()->SetPoint(4, 0, std::nan(""), 0);
  Result bad = tangentsOf(plane);
  EXPECT_EQ(bad.errors, 1);
  EXPECT_EQ(bad.out->GetNumberOfPoints(), 0);
}
