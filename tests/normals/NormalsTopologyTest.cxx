// slPolyDataNormals: face normals, splitting, orientation, cell types,
// degenerate and bad input, welding. Expected values are analytic, or
// vtkPolyDataNormals' where it computes the same thing.
#include "NormalsTestMeshes.h"

#include "slMeshReader.h"
#include "slPolyDataNormals.h"

#include <vtkCallbackCommand.h>
#include <vtkCleanPolyData.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkFeatureEdges.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyDataNormals.h>

#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <functional>
#include <map>
#include <random>
#include <string>

namespace
{
using normalstest::Vec;

vtkSmartPointer<vtkPolyData> mesh(const std::vector<Vec>& pts, const std::vector<std::vector<vtkIdType>>& polys)
{
  auto m = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  for (const Vec& p : pts)
  {
    points->InsertNextPoint(p.data());
  }
  vtkNew<vtkCellArray> cells;
  for (const auto& c : polys)
  {
    cells->InsertNextCell(static_cast<vtkIdType>(c.size()), c.data());
  }
  m->SetPoints(points);
  m->SetPolys(cells);
  return m;
}

/// A unit cube [0,1]^3 of six outward quads.
vtkSmartPointer<vtkPolyData> cube()
{
  return mesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } },
    { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 2, 3, 7, 6 }, { 0, 4, 7, 3 }, { 1, 2, 6, 5 } });
}

vtkSmartPointer<vtkPolyData> icosphere(int levels)
{
  std::vector<Vec> pts;
  std::vector<std::array<vtkIdType, 3>> tris;
  normalstest::icosphere(levels, pts, tris);
  return normalstest::makePolyData(pts, tris, pts);
}

struct Result
{
  vtkSmartPointer<vtkPolyData> out;
  int errors = 0, warnings = 0;
  vtkIdType flipped = 0;
  std::string lastError;
};

Result run(vtkPolyData* input, const std::function<void(slPolyDataNormals*)>& configure = {})
{
  vtkNew<slPolyDataNormals> f;
  f->SetInputData(input);
  if (configure)
  {
    configure(f);
  }
  Result r;
  vtkNew<vtkCallbackCommand> count;
  count->SetClientData(&r);
  count->SetCallback([](vtkObject*, unsigned long event, void* data, void* message) {
    auto* run = static_cast<Result*>(data);
    (event == vtkCommand::ErrorEvent ? run->errors : run->warnings)++;
    if (event == vtkCommand::ErrorEvent && message)
    {
      run->lastError = static_cast<const char*>(message);
    }
  });
  f->AddObserver(vtkCommand::ErrorEvent, count);
  f->AddObserver(vtkCommand::WarningEvent, count);
  f->Update();
  r.out = f->GetOutput();
  r.flipped = f->GetNumberOfFlippedPolygons();
  return r;
}

Vec tuple(vtkDataArray* a, vtkIdType i)
{
  Vec v;
  a->GetTuple(i, v.data());
  return v;
}

/// The normals of the output points at the origin, which must be unit
/// vectors along z, one facing -z and one +z (two apexes meeting there).
void expectApexesFacingApart(vtkPolyData* out)
{
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  std::vector<double> apexZ;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    if (p[0] == 0 && p[1] == 0 && p[2] == 0)
    {
      const Vec nv = tuple(normals, i);
      EXPECT_NEAR(std::fabs(nv[2]), 1.0, 1e-6);
      apexZ.push_back(nv[2]);
    }
  }
  ASSERT_EQ(apexZ.size(), 2u);
  EXPECT_NEAR(apexZ[0] + apexZ[1], 0.0, 1e-6);
}

void expectNear(const Vec& a, const Vec& b, double tol = 1e-6)
{
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_NEAR(a[k], b[k], tol) << "component " << k;
  }
}
} // namespace

TEST(Normals, NewellFaceNormalsForTrianglesAndNonConvexPolygons)
{
  // A non-convex hexagon ("L" shape) and a triangle in the plane x + 2y + 2z = 3.
  const Vec n = { 1.0 / 3, 2.0 / 3, 2.0 / 3 };
  const Vec u = normalstest::normalized({ 2, -1, 0 });
  const Vec v = { n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0] }; // n x u
  std::vector<Vec> pts;
  for (const auto& st : std::vector<std::array<double, 2>>{ { 0, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 }, { 1, 2 }, { 0, 2 } })
  {
    pts.push_back({ n[0] + st[0] * u[0] + st[1] * v[0], n[1] + st[0] * u[1] + st[1] * v[1],
      n[2] + st[0] * u[2] + st[1] * v[2] });
  }
  Result r = run(mesh(pts, { { 0, 1, 2, 3, 4, 5 }, { 0, 1, 5 } }), [](slPolyDataNormals* f) {
    f->ComputeCellNormalsOn();
    f->ConsistencyOff(); // the two overlap, both anticlockwise about n
  });
  vtkDataArray* cn = r.out->GetCellData()->GetNormals();
  ASSERT_NE(cn, nullptr);
  EXPECT_STREQ(cn->GetName(), "Normals");
  expectNear(tuple(cn, 0), n);
  expectNear(tuple(cn, 1), n);
}

TEST(Normals, CubeSplitsAlongItsEdgesIntoTwentyFourPoints)
{
  Result r = run(cube());
  ASSERT_EQ(r.out->GetNumberOfPoints(), 24);
  vtkDataArray* normals = r.out->GetPointData()->GetNormals();
  ASSERT_NE(normals, nullptr);
  // Every corner's normal is the axis of its face: the outward direction
  // from the cube's centre along the coordinate where the point is 0 or 1.
  for (vtkIdType c = 0; c < r.out->GetNumberOfPolys(); ++c)
  {
    vtkNew<vtkIdList> ids;
    r.out->GetPolys()->GetCellAtId(c, ids);
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
    {
      const Vec nv = tuple(normals, ids->GetId(i));
      double p[3];
      r.out->GetPoint(ids->GetId(i), p);
      int axis = std::fabs(nv[0]) > 0.5 ? 0 : (std::fabs(nv[1]) > 0.5 ? 1 : 2);
      Vec expected = { 0, 0, 0 };
      expected[axis] = p[axis] > 0.5 ? 1 : -1;
      expectNear(nv, expected);
    }
  }
}

TEST(Normals, CubeCornersAreDiagonalWhenEdgesAreSmoothAndAngleWeightingIgnoresTessellation)
{
  // Split the bottom quad (0,3,2,1) in two triangles: at corner 0 that face
  // now has two 45 degree corners instead of one 90 degree corner.
  vtkSmartPointer<vtkPolyData> m =
    mesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } },
      { { 0, 3, 2 }, { 0, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 2, 3, 7, 6 }, { 0, 4, 7, 3 }, { 1, 2, 6, 5 } });
  const double s = 1 / std::sqrt(3.0);
  Result angle = run(m, [](slPolyDataNormals* f) { f->SetFeatureAngle(100); });
  ASSERT_EQ(angle.out->GetNumberOfPoints(), 8);
  expectNear(tuple(angle.out->GetPointData()->GetNormals(), 0), { -s, -s, -s });
  // Uniform weighting counts the split face twice: (-1,-1,-2)/sqrt(6).
  Result uniform = run(m, [](slPolyDataNormals* f) {
    f->SetFeatureAngle(100);
    f->SetWeightingToUniform();
  });
  const double t = 1 / std::sqrt(6.0);
  expectNear(tuple(uniform.out->GetPointData()->GetNormals(), 0), { -t, -t, -2 * t });
}

TEST(Normals, SmoothEdgesStaySharedAndPointDataFollowsSplitPoints)
{
  Result sphere = run(icosphere(2));
  EXPECT_EQ(sphere.out->GetNumberOfPoints(), icosphere(2)->GetNumberOfPoints());

  vtkSmartPointer<vtkPolyData> c = cube();
  vtkNew<vtkIntArray> label;
  label->SetName("Label");
  for (int i = 0; i < 8; ++i)
  {
    label->InsertNextValue(100 + i);
  }
  c->GetPointData()->AddArray(label);
  Result r = run(c);
  vtkDataArray* out = r.out->GetPointData()->GetArray("Label");
  ASSERT_NE(out, nullptr);
  for (vtkIdType i = 0; i < r.out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    r.out->GetPoint(i, p);
    const int expected = 100 + static_cast<int>(c->FindPoint(p));
    EXPECT_EQ(out->GetTuple1(i), expected) << "point " << i;
  }
}

TEST(Normals, ConsistencyReversesWronglyOrientedTrianglesAndAutoOrientTurnsOutward)
{
  vtkSmartPointer<vtkPolyData> s = icosphere(2);
  auto reversed = [](vtkPolyData* m, const std::vector<vtkIdType>& which) {
    vtkNew<vtkCellArray> cells;
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < m->GetNumberOfPolys(); ++c)
    {
      m->GetPolys()->GetCellAtId(c, ids);
      if (which.empty() || std::find(which.begin(), which.end(), c) != which.end())
      {
        std::swap(ids->GetPointer(0)[1], ids->GetPointer(0)[2]);
      }
      cells->InsertNextCell(ids);
    }
    auto out = vtkSmartPointer<vtkPolyData>::New();
    out->SetPoints(m->GetPoints());
    out->SetPolys(cells);
    return out;
  };
  auto outward = [](const Result& r) {
    int inward = 0;
    vtkDataArray* n = r.out->GetPointData()->GetNormals();
    for (vtkIdType i = 0; i < r.out->GetNumberOfPoints(); ++i)
    {
      double p[3];
      r.out->GetPoint(i, p);
      const Vec nv = tuple(n, i);
      inward += p[0] * nv[0] + p[1] * nv[1] + p[2] * nv[2] < 0.9;
    }
    return inward == 0;
  };
  Result fixed = run(reversed(s, { 3, 17, 40, 41, 100 }));
  EXPECT_EQ(fixed.flipped, 5);
  EXPECT_TRUE(outward(fixed));

  Result off = run(reversed(s, { 3, 17, 40, 41, 100 }), [](slPolyDataNormals* f) { f->ConsistencyOff(); });
  EXPECT_EQ(off.flipped, 0);
  EXPECT_FALSE(outward(off));

  Result inverted = run(reversed(s, {}), [](slPolyDataNormals* f) { f->AutoOrientNormalsOn(); });
  EXPECT_EQ(inverted.flipped, s->GetNumberOfPolys());
  EXPECT_TRUE(outward(inverted));
}

TEST(Normals, StripsBecomeTrianglesWithTheStripsOrientation)
{
  auto m = mesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 0, 2, 0 } }, {});
  vtkNew<vtkCellArray> strips;
  const vtkIdType ids[] = { 0, 1, 2, 3, 4 };
  strips->InsertNextCell(5, ids);
  m->SetStrips(strips);
  vtkNew<vtkIntArray> tag;
  tag->SetName("Tag");
  tag->InsertNextValue(7);
  m->GetCellData()->AddArray(tag);
  Result r = run(m, [](slPolyDataNormals* f) { f->ComputeCellNormalsOn(); });
  ASSERT_EQ(r.out->GetNumberOfPolys(), 3);
  EXPECT_EQ(r.out->GetNumberOfStrips(), 0);
  // (P1-P0) x (P2-P0) = +z for the strip's first triangle; all follow it.
  for (vtkIdType c = 0; c < 3; ++c)
  {
    expectNear(tuple(r.out->GetCellData()->GetNormals(), c), { 0, 0, 1 });
    EXPECT_EQ(r.out->GetCellData()->GetArray("Tag")->GetTuple1(c), 7);
  }
  for (vtkIdType p = 0; p < 5; ++p)
  {
    expectNear(tuple(r.out->GetPointData()->GetNormals(), p), { 0, 0, 1 });
  }
}

TEST(Normals, ZeroAreaFacesAndIsolatedPointsGiveNoNaN)
{
  // Point 3 repeats point 1: triangle (1,2,3) has zero area. Point 4 is unused.
  auto m = mesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 0, 0 }, { 5, 5, 5 } }, { { 0, 1, 2 }, { 1, 3, 2 } });
  for (int w = 0; w < 4; ++w)
  {
    Result r = run(m, [w](slPolyDataNormals* f) {
      f->SetWeighting(w);
      f->ComputeCellNormalsOn();
    });
    EXPECT_EQ(r.errors, 0);
    vtkDataArray* n = r.out->GetPointData()->GetNormals();
    ASSERT_EQ(r.out->GetNumberOfPoints(), 5); // no sharp edge: points keep their ids
    // Points 0-2 see the good triangle; point 3 only the degenerate one and
    // point 4 nothing: both get (0,0,0).
    const std::vector<Vec> expected = { { 0, 0, 1 }, { 0, 0, 1 }, { 0, 0, 1 }, { 0, 0, 0 }, { 0, 0, 0 } };
    for (vtkIdType i = 0; i < 5; ++i)
    {
      expectNear(tuple(n, i), expected[static_cast<size_t>(i)]);
    }
    expectNear(tuple(r.out->GetCellData()->GetNormals(), 1), { 0, 0, 0 });
  }
}

TEST(Normals, ZeroAreaFacesDoNotJoinFacesAcrossASharpEdge)
{
  // A cube whose front face is cut at (0.5, 0, 0) of its bottom edge, the
  // crack along that edge filled with the zero-area triangle (0, 1, 8), as
  // CAD exports do. The bottom and front faces still meet at a sharp edge:
  // each corner of the cube along it has the three face axes as normals,
  // as if the degenerate triangle were not there, and none is (0, 0, 0).
  auto m = mesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 0, 0, 1 }, { 1, 0, 1 }, { 0, 1, 1 }, { 1, 1, 1 },
                  { 0.5, 0, 0 } },
    { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 }, { 0, 8, 5, 4 }, { 8, 1, 5 },
      { 0, 1, 8 } });
  Result r = run(m);
  EXPECT_EQ(r.errors, 0);
  vtkDataArray* n = r.out->GetPointData()->GetNormals();
  std::map<std::vector<double>, std::vector<Vec>> normalsAt;
  for (vtkIdType i = 0; i < r.out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    r.out->GetPoint(i, p);
    normalsAt[{ p[0], p[1], p[2] }].push_back(tuple(n, i));
  }
  const auto expectAxes = [&](const std::vector<double>& at, const std::vector<Vec>& axes) {
    std::vector<Vec> got = normalsAt[at];
    ASSERT_EQ(got.size(), axes.size()) << at[0] << " " << at[1] << " " << at[2];
    for (const Vec& axis : axes)
    {
      const bool found = std::any_of(got.begin(), got.end(), [&](const Vec& g) {
        return std::fabs(g[0] - axis[0]) < 1e-6 && std::fabs(g[1] - axis[1]) < 1e-6 && std::fabs(g[2] - axis[2]) < 1e-6;
      });
      EXPECT_TRUE(found) << "(" << axis[0] << ", " << axis[1] << ", " << axis[2] << ") at " << at[0];
    }
  };
  expectAxes({ 0, 0, 0 }, { { -1, 0, 0 }, { 0, -1, 0 }, { 0, 0, -1 } });
  expectAxes({ 1, 0, 0 }, { { 1, 0, 0 }, { 0, -1, 0 }, { 0, 0, -1 } });
  // The cut point lies on the front face only (the bottom face does not
  // name it): the degenerate triangle takes the front face's group there.
  expectAxes({ 0.5, 0, 0 }, { { 0, -1, 0 } });
}

TEST(Normals, NonManifoldEdgesAreSplit)
{
  // Three triangles share the edge (0,1); each is its own smooth group there.
  auto m = mesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 }, { 0.5, -1, 0.01 }, { 0.5, 0, 1 } },
    { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } });
  Result r = run(m, [](slPolyDataNormals* f) {
    f->ConsistencyOff();
    f->SetFeatureAngle(180);
  });
  EXPECT_EQ(r.out->GetNumberOfPoints(), 3 + 3 + 3);
}

TEST(Normals, VerticesAndLinesPassThroughWithAWarning)
{
  auto m = cube();
  vtkNew<vtkCellArray> verts, lines;
  const vtkIdType v[] = { 6 }, l[] = { 0, 6 };
  verts->InsertNextCell(1, v);
  lines->InsertNextCell(2, l);
  m->SetVerts(verts);
  m->SetLines(lines);
  Result r = run(m);
  EXPECT_EQ(r.warnings, 1);
  EXPECT_EQ(r.out->GetNumberOfVerts(), 1);
  EXPECT_EQ(r.out->GetNumberOfLines(), 1);
  EXPECT_EQ(r.out->GetNumberOfPolys(), 6);
  vtkNew<vtkIdList> ids;
  r.out->GetLines()->GetCellAtId(0, ids);
  double p[3];
  r.out->GetPoint(ids->GetId(1), p);
  EXPECT_EQ(Vec({ p[0], p[1], p[2] }), Vec({ 1, 1, 1 }));
}

TEST(Normals, NaNCoordinatesGiveAnErrorAndAnEmptyOutput)
{
  for (double bad : { std::nan(""), HUGE_VAL })
  {
    auto m = mesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, bad, 0 } }, { { 0, 1, 2 } });
    Result r = run(m);
    EXPECT_EQ(r.errors, 1);
    EXPECT_EQ(r.out->GetNumberOfPoints(), 0);
    EXPECT_EQ(r.out->GetNumberOfCells(), 0);
  }
}

TEST(Normals, TheFirstOfManyNonFinitePointsIsNamed)
{
  // Float points are checked in parallel pieces (of 16,384 points): one bad
  // point in each of two pieces, and the error must name the first of them
  // whichever piece is checked first.
  std::vector<std::array<double, 3>> points(70000);
  for (size_t i = 0; i < points.size(); ++i)
  {
    points[i] = { static_cast<double>(i % 97), static_cast<double>(i / 97), 0.0 };
  }
  points[65000][2] = HUGE_VAL;
  points[40000][1] = std::nan("");
  auto m = mesh(points, { { 0, 1, 97 } });
  Result r = run(m);
  EXPECT_EQ(r.errors, 1);
  EXPECT_NE(r.lastError.find("point 40000 has a NaN or infinite coordinate"), std::string::npos) << r.lastError;
  EXPECT_EQ(r.out->GetNumberOfPoints(), 0);
}

TEST(Normals, WeldingHidesTheTeapotsUnweldedSeams)
{
  // The teapot's patches repeat their seam points. Welding must give the
  // normals of the mesh merged by VTK's own vtkCleanPolyData, while keeping
  // every input point; without welding the seams show as creases.
  vtkNew<slMeshReader> reader;
  reader->SetFileName(SHADELAB_DATA_DIR "/meshes/teapot.obj");
  reader->MergeDuplicatePointsOff();
  reader->Update();
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputData(reader->GetOutput());
  clean->SetTolerance(0.0);
  clean->Update();
  ASSERT_GT(reader->GetOutput()->GetNumberOfPoints(), clean->GetOutput()->GetNumberOfPoints());
  auto configure = [](bool weld) {
    return [weld](slPolyDataNormals* f) {
      f->SplittingOff();
      f->ConsistencyOff();
      f->SetWeldCoincidentPoints(weld);
    };
  };
  Result welded = run(reader->GetOutput(), configure(true));
  Result plain = run(reader->GetOutput(), configure(false));
  Result reference = run(clean->GetOutput(), configure(false));
  ASSERT_EQ(welded.out->GetNumberOfPoints(), reader->GetOutput()->GetNumberOfPoints());
  double worstWelded = 0, worstPlain = 0;
  for (vtkIdType i = 0; i < welded.out->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    welded.out->GetPoint(i, p);
    const vtkIdType j = reference.out->FindPoint(p);
    reference.out->GetPoint(j, q);
    ASSERT_EQ(Vec({ p[0], p[1], p[2] }), Vec({ q[0], q[1], q[2] }));
    double a[3], b[3], c[3];
    welded.out->GetPointData()->GetNormals()->GetTuple(i, a);
    plain.out->GetPointData()->GetNormals()->GetTuple(i, b);
    reference.out->GetPointData()->GetNormals()->GetTuple(j, c);
    worstWelded = std::max(worstWelded, normalstest::angleDegrees(a, c));
    worstPlain = std::max(worstPlain, normalstest::angleDegrees(b, c));
  }
  EXPECT_LT(worstWelded, 1e-3);
  EXPECT_GT(worstPlain, 20.0);
}

TEST(Normals, WeldingWithSplittingLeavesNoOrphanPoints)
{
  // Spot's OBJ repeats points along its UV seams. Welded and split, every
  // output point must be used by a polygon and have a unit normal: seam
  // duplicates must not come back as extra unused points with zero normals.
  vtkNew<slMeshReader> reader;
  reader->SetFileName(SHADELAB_DATA_DIR "/meshes/spot.obj");
  reader->Update();
  Result r = run(reader->GetOutput(), [](slPolyDataNormals* f) {
    f->SplittingOn();
    f->SetFeatureAngle(30.0);
    f->ConsistencyOn();
    f->WeldCoincidentPointsOn();
  });
  std::vector<int> uses(static_cast<size_t>(r.out->GetNumberOfPoints()), 0);
  vtkIdType npts;
  const vtkIdType* pts;
  vtkCellArray* polys = r.out->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, pts);)
  {
    for (vtkIdType k = 0; k < npts; ++k)
    {
      ++uses[static_cast<size_t>(pts[k])];
    }
  }
  for (vtkIdType i = 0; i < r.out->GetNumberOfPoints(); ++i)
  {
    ASSERT_GT(uses[static_cast<size_t>(i)], 0) << "point " << i << " of " << r.out->GetNumberOfPoints();
    double n[3];
    r.out->GetPointData()->GetNormals()->GetTuple(i, n);
    ASSERT_NEAR(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 1.0, 1e-5) << "point " << i;
  }
}

TEST(Normals, WeldedUnusedPointTakesTheNormalOfItsPositionOnlyWithoutSplitting)
{
  // A unit square in z = 0 (normal +z), point 4 unused at the position of
  // point 0, point 5 unused elsewhere. Welding without splitting gives
  // point 4 the square's normal: one position, one normal. With splitting a
  // position may have several normals, so unused points keep (0, 0, 0), as
  // point 5 does in both.
  vtkSmartPointer<vtkPolyData> square =
    mesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 0 }, { 5, 5, 5 } }, { { 0, 1, 2, 3 } });
  auto normalAt = [](const Result& r, vtkIdType p) {
    double n[3];
    r.out->GetPointData()->GetNormals()->GetTuple(p, n);
    return Vec({ n[0], n[1], n[2] });
  };
  Result smooth = run(square, [](slPolyDataNormals* f) {
    f->SplittingOff();
    f->WeldCoincidentPointsOn();
  });
  ASSERT_EQ(smooth.out->GetNumberOfPoints(), 6);
  EXPECT_EQ(normalAt(smooth, 0), Vec({ 0, 0, 1 }));
  EXPECT_EQ(normalAt(smooth, 4), Vec({ 0, 0, 1 }));
  EXPECT_EQ(normalAt(smooth, 5), Vec({ 0, 0, 0 }));

  Result split = run(square, [](slPolyDataNormals* f) {
    f->SplittingOn();
    f->WeldCoincidentPointsOn();
  });
  ASSERT_EQ(split.out->GetNumberOfPoints(), 6);
  // Used points first, in the polygon's order; the unused ones last, in input order.
  for (vtkIdType p = 0; p < 4; ++p)
  {
    EXPECT_EQ(normalAt(split, p), Vec({ 0, 0, 1 })) << "point " << p;
  }
  double p4[3], p5[3];
  split.out->GetPoint(4, p4);
  split.out->GetPoint(5, p5);
  EXPECT_EQ(Vec({ p4[0], p4[1], p4[2] }), Vec({ 0, 0, 0 }));
  EXPECT_EQ(Vec({ p5[0], p5[1], p5[2] }), Vec({ 5, 5, 5 }));
  EXPECT_EQ(normalAt(split, 4), Vec({ 0, 0, 0 }));
  EXPECT_EQ(normalAt(split, 5), Vec({ 0, 0, 0 }));
}

TEST(Normals, PointsThatAreNotOneSmoothClosedFanTakeTheGeneralGrouping)
{
  // Most points are one smooth closed fan (one group, found by a walk around
  // the fan); every other case must still group as the general pass does.
  vtkSmartPointer<vtkPolyData> s = icosphere(2);
  const vtkIdType n = s->GetNumberOfPoints();
  auto rebuilt = [&](vtkIdType reverse, vtkIdType drop) {
    vtkNew<vtkCellArray> cells;
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < s->GetNumberOfPolys(); ++c)
    {
      s->GetPolys()->GetCellAtId(c, ids);
      if (c == reverse)
      {
        std::swap(ids->GetPointer(0)[1], ids->GetPointer(0)[2]);
      }
      if (c != drop)
      {
        cells->InsertNextCell(ids);
      }
    }
    auto out = vtkSmartPointer<vtkPolyData>::New();
    out->SetPoints(s->GetPoints());
    out->SetPolys(cells);
    return out;
  };

  // A reversed triangle, left reversed: its normal is opposite its
  // neighbours', so its three points each gain a group.
  Result wrongWay = run(rebuilt(3, -1), [](slPolyDataNormals* f) { f->ConsistencyOff(); });
  EXPECT_EQ(wrongWay.out->GetNumberOfPoints(), n + 3);
  // Found by the grouping pass itself and reversed: nothing splits.
  Result fixed = run(rebuilt(3, -1));
  EXPECT_EQ(fixed.flipped, 1);
  EXPECT_EQ(fixed.out->GetNumberOfPoints(), n);

  // A hole: the points around it are open fans, still one group each.
  Result open = run(rebuilt(-1, 3));
  EXPECT_EQ(open.out->GetNumberOfPoints(), n);

  // A bowtie: two square pyramids meet at their apex (point 0). Each is a
  // smooth closed fan of four triangles there, but the apex has eight
  // corners in two fans, so it becomes two points, facing -z and +z.
  auto bowtie = mesh({ { 0, 0, 0 }, { 1, 1, 1 }, { -1, 1, 1 }, { -1, -1, 1 }, { 1, -1, 1 }, { 1, 1, -1 },
                       { 1, -1, -1 }, { -1, -1, -1 }, { -1, 1, -1 } },
    { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 3, 4 }, { 0, 4, 1 }, { 0, 5, 6 }, { 0, 6, 7 }, { 0, 7, 8 }, { 0, 8, 5 } });
  Result tie = run(bowtie, [](slPolyDataNormals* f) { f->SetFeatureAngle(180); });
  ASSERT_EQ(tie.out->GetNumberOfPoints(), 10);
  expectApexesFacingApart(tie.out);
}

TEST(Normals, FansOfManyCornersGroupAsFansOfFew)
{
  // Double cones (two open cones of n sides, apex to apex at the origin,
  // 45 degrees): the apex has 2n corners in two smooth closed fans, and
  // becomes two points facing -z and +z, whether the fan walk hashes its
  // steps (up to 32 corners) or scans for them. Neighbouring sides are
  // 25 degrees apart or less (n >= 10), under the 30 degree feature angle.
  for (const int n : { 10, 16, 17, 40 })
  {
    std::vector<Vec> pts = { { 0, 0, 0 } };
    std::vector<std::vector<vtkIdType>> tris;
    for (const double z : { 1.0, -1.0 })
    {
      const vtkIdType first = static_cast<vtkIdType>(pts.size());
      for (int i = 0; i < n; ++i)
      {
        const double a = 2 * M_PI * i / n;
        pts.push_back({ std::cos(a), std::sin(a), z });
      }
      for (vtkIdType i = 0; i < n; ++i)
      {
        const vtkIdType b = first + i, c = first + (i + 1) % n;
        // Every side faces away from the axis, so both cones run the same way.
        tris.push_back(z > 0 ? std::vector<vtkIdType>{ 0, c, b } : std::vector<vtkIdType>{ 0, b, c });
      }
    }
    Result cones = run(mesh(pts, tris));
    ASSERT_EQ(cones.out->GetNumberOfPoints(), 2 * n + 2) << n << " sides";
    // A side's normal is (cos a, sin a, -1) / sqrt 2 on the upper cone and
    // (cos a, sin a, 1) / sqrt 2 on the lower: over a full turn the sums
    // point along the axis, -z and +z.
    SCOPED_TRACE(std::to_string(n) + " sides");
    expectApexesFacingApart(cones.out);
  }
}

TEST(Normals, AFilterRunAgainOnAnotherMeshGivesWhatANewFilterGives)
{
  // The filter keeps its scratch memory between updates: the second mesh
  // (same size, other shape, splits at most points) gets the memory the
  // first one wrote, and must not see what is in it.
  auto first = normalstest::irregularTorus(1.0, 0.3, 300, 150, 1);
  auto second = normalstest::irregularTorus(1.0, 0.3, 300, 150, 2);
  vtkNew<slPolyDataNormals> reused, fresh;
  reused->SetFeatureAngle(1.0);
  fresh->SetFeatureAngle(1.0);
  reused->SetInputData(first);
  reused->Update();
  reused->SetInputData(second);
  reused->Update();
  fresh->SetInputData(second);
  fresh->Update();
  vtkPolyData* a = reused->GetOutput();
  vtkPolyData* b = fresh->GetOutput();
  ASSERT_GT(b->GetNumberOfPoints(), 2 * second->GetNumberOfPoints()); // split at most points
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  ASSERT_EQ(a->GetPolys()->GetNumberOfConnectivityIds(), b->GetPolys()->GetNumberOfConnectivityIds());
  auto sameValues = [](vtkDataArray* x, vtkDataArray* y) {
    const vtkIdType n = x->GetNumberOfValues();
    if (n != y->GetNumberOfValues())
    {
      return false;
    }
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (x->GetVariantValue(i) != y->GetVariantValue(i))
      {
        return false;
      }
    }
    return true;
  };
  EXPECT_TRUE(sameValues(a->GetPointData()->GetNormals(), b->GetPointData()->GetNormals()));
  EXPECT_TRUE(sameValues(a->GetPoints()->GetData(), b->GetPoints()->GetData()));
  EXPECT_TRUE(sameValues(a->GetPolys()->GetConnectivityArray(), b->GetPolys()->GetConnectivityArray()));
}

TEST(Normals, CreasedClosedSurfaceSplitsAsVTKPolyDataNormals)
{
  // An icosphere with its points moved out at random: a closed surface whose
  // points have zero, one, two or more sharp edges (over 30 degrees) around
  // them. A closed fan's groups are the runs between its sharp edges, one
  // group when it has only one; vtkPolyDataNormals, which finds the groups
  // by walking across smooth edges, must make the same points, and with
  // uniform weighting the same normals.
  std::vector<Vec> pts;
  std::vector<std::array<vtkIdType, 3>> tris;
  normalstest::icosphere(3, pts, tris);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> radius(1.0, 1.3);
  for (Vec& p : pts)
  {
    const double r = radius(rng);
    p = { r * p[0], r * p[1], r * p[2] };
  }
  vtkSmartPointer<vtkPolyData> bumpy = normalstest::makePolyData(pts, tris, pts);

  // The cases must all be there: points with 1, 2 and 3 or more sharp edges.
  vtkNew<vtkFeatureEdges> sharp;
  sharp->SetInputData(bumpy);
  sharp->BoundaryEdgesOff();
  sharp->NonManifoldEdgesOff();
  sharp->ManifoldEdgesOff();
  sharp->FeatureEdgesOn();
  sharp->SetFeatureAngle(30);
  sharp->Update();
  std::map<std::array<double, 3>, int> sharpAt;
  vtkPolyData* edges = sharp->GetOutput();
  for (vtkIdType i = 0; i < edges->GetNumberOfPoints(); ++i)
  {
    sharpAt[{ edges->GetPoint(i)[0], edges->GetPoint(i)[1], edges->GetPoint(i)[2] }] = 0;
  }
  vtkNew<vtkIdList> ends;
  for (vtkIdType e = 0; e < edges->GetNumberOfCells(); ++e)
  {
    edges->GetCellPoints(e, ends);
    for (vtkIdType k = 0; k < ends->GetNumberOfIds(); ++k)
    {
      const double* p = edges->GetPoint(ends->GetId(k));
      ++sharpAt[{ p[0], p[1], p[2] }];
    }
  }
  std::map<int, int> pointsWith;
  for (const auto& at : sharpAt)
  {
    ++pointsWith[std::min(at.second, 3)];
  }
  ASSERT_GT(pointsWith[1], 10);
  ASSERT_GT(pointsWith[2], 10);
  ASSERT_GT(pointsWith[3], 10);

  Result ours = run(bumpy, [](slPolyDataNormals* f) { f->SetWeighting(slPolyDataNormals::UNIFORM); });
  vtkNew<vtkPolyDataNormals> vtk;
  vtk->SetInputData(bumpy);
  vtk->Update();
  ASSERT_EQ(ours.out->GetNumberOfPoints(), vtk->GetOutput()->GetNumberOfPoints());
  ASSERT_GT(ours.out->GetNumberOfPoints(), bumpy->GetNumberOfPoints());
  // Each position's normals, sorted, from both.
  auto normalsAt = [](vtkPolyData* out) {
    std::map<std::array<double, 3>, std::vector<Vec>> at;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      const double* p = out->GetPoint(i);
      at[{ p[0], p[1], p[2] }].push_back(tuple(out->GetPointData()->GetNormals(), i));
    }
    for (auto& point : at)
    {
      std::sort(point.second.begin(), point.second.end());
    }
    return at;
  };
  const auto a = normalsAt(ours.out), b = normalsAt(vtk->GetOutput());
  ASSERT_EQ(a.size(), b.size());
  for (auto i = a.begin(), j = b.begin(); i != a.end(); ++i, ++j)
  {
    ASSERT_EQ(i->first, j->first);
    ASSERT_EQ(i->second.size(), j->second.size()) << "groups at a point";
    for (size_t g = 0; g < i->second.size(); ++g)
    {
      expectNear(i->second[g], j->second[g], 1e-5);
    }
  }
}
