// slPolyDataNormals on inputs at the edges of floating-point range: double
// meshes of extreme size (analytic normals of cubes and spheres) and Max
// weighting at near-coincident points, where 1 / (|e1|² |e2|²) would
// overflow. Every normal must be finite, and of unit length where a point
// has a polygon of non-zero area.
#include "NormalsTestMeshes.h"

#include "slPolyDataNormals.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace
{
vtkSmartPointer<vtkPolyData> meshOf(
  const std::vector<normalstest::Vec>& pts, const std::vector<std::vector<vtkIdType>>& polys, int type)
{
  vtkNew<vtkPoints> points;
  points->SetDataType(type);
  for (const auto& p : pts)
  {
    points->InsertNextPoint(p[0], p[1], p[2]);
  }
  vtkNew<vtkCellArray> cells;
  for (const auto& c : polys)
  {
    cells->InsertNextCell(static_cast<vtkIdType>(c.size()), c.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(cells);
  return mesh;
}

vtkSmartPointer<vtkPolyData> normalsOf(
  vtkPolyData* mesh, int weighting, bool split, double featureAngle = 30.0, bool weld = false)
{
  vtkNew<slPolyDataNormals> f;
  f->SetInputData(mesh);
  f->SetWeldCoincidentPoints(weld);
  f->SetWeighting(weighting);
  f->SetSplitting(split);
  f->SetFeatureAngle(featureAngle);
  f->ConsistencyOff();
  f->Update();
  vtkSmartPointer<vtkPolyData> out = f->GetOutput();
  return out;
}

/// Cube [-s, s]^3 as six outward quads.
vtkSmartPointer<vtkPolyData> cube(double s)
{
  std::vector<normalstest::Vec> pts;
  for (int i = 0; i < 8; ++i)
  {
    pts.push_back({ i & 1 ? s : -s, i & 2 ? s : -s, i & 4 ? s : -s });
  }
  return meshOf(pts, { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 1, 3, 7, 5 }, { 0, 4, 6, 2 } },
    VTK_DOUBLE);
}

/// Whether @p n (3 floats as doubles) is finite and of unit length to
/// @p tolerance.
bool isUnit(const double* n, double tolerance = 1e-6)
{
  return std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]) &&
    std::abs(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1.0) < tolerance;
}
} // namespace

TEST(NormalsRange, DoubleCubesOfExtremeSizeGetAnalyticNormals)
{
  // The squared cross products of edges grow as the 4th power of the size:
  // in double they overflow above about 1e77 and underflow below about
  // 1e-77 (NaN or zero normals, no split). Split, each output point of a
  // cube has its face's axis normal; unsplit, each corner the diagonal
  // (1, 1, 1) / sqrt(3) up to signs, for every weighting (the three faces
  // at a corner are alike).
  for (double s : { 1e-300, 1e-150, 1e-100, 1e-80, 1.0, 1e80, 1e100, 1e150, 1e155, 1e300 })
  {
    for (int weighting = slPolyDataNormals::UNIFORM; weighting <= slPolyDataNormals::MAX; ++weighting)
    {
      const std::string what = "size " + std::to_string(std::log10(s)) + ", " +
        slPolyDataNormals::GetWeightingName(weighting);
      vtkSmartPointer<vtkPolyData> split = normalsOf(cube(s), weighting, true);
      ASSERT_EQ(split->GetNumberOfPoints(), 24) << what;
      ASSERT_EQ(split->GetPoints()->GetDataType(), VTK_DOUBLE) << what;
      for (vtkIdType i = 0; i < 24; ++i)
      {
        double p[3], n[3];
        split->GetPoint(i, p);
        split->GetPointData()->GetNormals()->GetTuple(i, n);
        ASSERT_TRUE(isUnit(n)) << what << ", point " << i << ": " << n[0] << " " << n[1] << " " << n[2];
        int axes = 0;
        for (int c = 0; c < 3; ++c)
        {
          EXPECT_TRUE(p[c] == s || p[c] == -s) << what << ", point " << i; // input coordinates, exactly
          if (std::abs(n[c]) > 0.5)
          {
            ++axes;
            EXPECT_EQ(n[c], p[c] > 0 ? 1.0 : -1.0) << what << ", point " << i;
          }
          else
          {
            EXPECT_EQ(n[c], 0.0) << what << ", point " << i;
          }
        }
        EXPECT_EQ(axes, 1) << what << ", point " << i;
      }
      vtkSmartPointer<vtkPolyData> smooth = normalsOf(cube(s), weighting, false);
      ASSERT_EQ(smooth->GetNumberOfPoints(), 8) << what;
      for (vtkIdType i = 0; i < 8; ++i)
      {
        double p[3], n[3];
        smooth->GetPoint(i, p);
        smooth->GetPointData()->GetNormals()->GetTuple(i, n);
        ASSERT_TRUE(isUnit(n)) << what << ", point " << i;
        for (int c = 0; c < 3; ++c)
        {
          EXPECT_NEAR(n[c], (p[c] > 0 ? 1.0 : -1.0) / std::sqrt(3.0), 1e-7) << what << ", point " << i;
        }
      }
    }
  }
}

TEST(NormalsRange, ClosedSurfacesOfExtremeSizeTurnOutward)
{
  // The signed volume's terms grow as the cube of the size: unscaled, they
  // overflow double beyond about 1e102 (inf - inf in a Newell vector not
  // along an axis: NaN) and underflow to 0 below about 1e-108. A cube
  // centred at the origin, turned off the axes and given inward (every face
  // reversed, consistent), must come out with each corner's normal along
  // the corner's own diagonal, p / |p|.
  const std::vector<std::pair<int, double>> cases = { { VTK_DOUBLE, 1e-300 }, { VTK_DOUBLE, 1e-120 },
    { VTK_DOUBLE, 1e-3 }, { VTK_DOUBLE, 1.0 }, { VTK_DOUBLE, 1e120 }, { VTK_DOUBLE, 1e300 }, { VTK_FLOAT, 1e-30 },
    { VTK_FLOAT, 1.0 }, { VTK_FLOAT, 1e20 }, { VTK_FLOAT, 1e30 } };
  for (const auto& c : cases)
  {
    const double s = c.second;
    // Rotation by 0.7 rad about (1, 2, 3) / sqrt(14) (Rodrigues).
    const double a[3] = { 1 / std::sqrt(14.0), 2 / std::sqrt(14.0), 3 / std::sqrt(14.0) };
    const double cs = std::cos(0.7), sn = std::sin(0.7);
    std::vector<normalstest::Vec> pts;
    for (int i = 0; i < 8; ++i)
    {
      const double v[3] = { i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0 };
      const double d = a[0] * v[0] + a[1] * v[1] + a[2] * v[2];
      const double x[3] = { a[1] * v[2] - a[2] * v[1], a[2] * v[0] - a[0] * v[2], a[0] * v[1] - a[1] * v[0] };
      normalstest::Vec p;
      for (int k = 0; k < 3; ++k)
      {
        p[k] = s * (v[k] * cs + x[k] * sn + a[k] * d * (1 - cs));
      }
      pts.push_back(p);
    }
    // cube()'s quads, each reversed.
    vtkSmartPointer<vtkPolyData> inward = meshOf(pts,
      { { 1, 3, 2, 0 }, { 6, 7, 5, 4 }, { 4, 5, 1, 0 }, { 3, 7, 6, 2 }, { 5, 7, 3, 1 }, { 2, 6, 4, 0 } }, c.first);
    vtkNew<slPolyDataNormals> f;
    f->SetInputData(inward);
    f->SetSplitting(false);
    f->ConsistencyOn();
    f->AutoOrientNormalsOn();
    f->Update();
    vtkPolyData* out = f->GetOutput();
    const std::string what = std::string(c.first == VTK_DOUBLE ? "double" : "float") + " cube of size " +
      std::to_string(std::log10(s));
    ASSERT_EQ(out->GetNumberOfPoints(), 8) << what;
    for (vtkIdType i = 0; i < 8; ++i)
    {
      double p[3], n[3];
      out->GetPoint(i, p);
      out->GetPointData()->GetNormals()->GetTuple(i, n);
      ASSERT_TRUE(isUnit(n)) << what << ", point " << i;
      const double length = std::hypot(p[0], p[1], p[2]);
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_NEAR(n[k], p[k] / length, 1e-5) << what << ", point " << i;
      }
    }
  }
}

TEST(NormalsRange, DoubleSpheresOfExtremeSizeGetRadialMaxNormals)
{
  // Max weighting is exact at the vertices of any triangulated sphere: the
  // normal at p is p / |p| at every size (VTK's filter gives NaN at 1e155).
  // Splitting at 30 degrees splits nothing here: points keep their ids.
  std::vector<normalstest::Vec> unit;
  std::vector<std::array<vtkIdType, 3>> tris;
  normalstest::icosphere(2, unit, tris);
  std::vector<std::vector<vtkIdType>> polys;
  for (const auto& t : tris)
  {
    polys.push_back({ t[0], t[1], t[2] });
  }
  for (double r : { 1e-300, 1e-150, 1e-100, 1.0, 1e80, 1e150, 1e155, 1e300 })
  {
    std::vector<normalstest::Vec> pts;
    for (const auto& p : unit)
    {
      pts.push_back({ r * p[0], r * p[1], r * p[2] });
    }
    for (bool split : { false, true })
    {
      const std::string what = "radius " + std::to_string(std::log10(r)) + (split ? ", split" : "");
      vtkSmartPointer<vtkPolyData> out = normalsOf(meshOf(pts, polys, VTK_DOUBLE), slPolyDataNormals::MAX, split);
      ASSERT_EQ(out->GetNumberOfPoints(), static_cast<vtkIdType>(unit.size())) << what;
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      {
        double n[3];
        out->GetPointData()->GetNormals()->GetTuple(i, n);
        ASSERT_TRUE(isUnit(n)) << what << ", point " << i;
        EXPECT_LT(normalstest::angleDegrees(n, unit[static_cast<size_t>(i)].data()), 1e-4) << what << ", point " << i;
      }
    }
  }
}

TEST(NormalsRange, MaxWeightingIsFiniteAtNearCoincidentPoints)
{
  // Point 6 lies 3e-20 (float) or 3e-160 (double) from point 1: the corners
  // between them have |e1|² |e2|² below the smallest normal number, whose
  // reciprocal overflowed (NaN and infinite normals, the triangle block
  // without splitting and the per-corner path with it). Such a corner
  // weighs 0; the expected normals are computed here in long double from
  // the same rounded coordinates, with Max's weight at every other corner:
  // at point 1 the normal of its other corners, at point 6, whose corners
  // are all such, (0, 0, 0).
  for (int type : { VTK_FLOAT, VTK_DOUBLE })
  {
    const double gap = type == VTK_FLOAT ? 3e-20 : 3e-160;
    const std::vector<normalstest::Vec> given = { { 0, 0, 1 }, { 0.4338837, 0, 0.9009688 },
      { 0.7818315, 0, 0.6234898 }, { 0.3068021, 0.3068021, 0.9009688 }, { 0.5528383, 0.5528383, 0.6234898 },
      { 0.3068021, -0.3068021, 0.9009688 }, { 0.4338837, gap, 0.9009688 } };
    const std::vector<std::vector<vtkIdType>> polys = { { 5, 1, 0 }, { 1, 2, 4 }, { 1, 4, 3 }, { 5, 2, 1 },
      { 1, 3, 6 }, { 1, 6, 0 } };
    vtkSmartPointer<vtkPolyData> mesh = meshOf(given, polys, type);
    const long double smallest = type == VTK_FLOAT ? std::numeric_limits<float>::min()
                                                   : std::numeric_limits<double>::min();
    std::vector<std::array<long double, 3>> expected(given.size(), { 0, 0, 0 });
    for (const auto& c : polys)
    {
      for (int k = 0; k < 3; ++k)
      {
        double a[3], b[3], q[3];
        mesh->GetPoint(c[k], a);
        mesh->GetPoint(c[(k + 1) % 3], b);
        mesh->GetPoint(c[(k + 2) % 3], q);
        const long double e1[3] = { static_cast<long double>(b[0]) - a[0], static_cast<long double>(b[1]) - a[1],
          static_cast<long double>(b[2]) - a[2] };
        const long double e2[3] = { static_cast<long double>(q[0]) - a[0], static_cast<long double>(q[1]) - a[1],
          static_cast<long double>(q[2]) - a[2] };
        const long double x[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
          e1[0] * e2[1] - e1[1] * e2[0] };
        const long double l = (e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]) *
          (e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2]);
        const long double w = l >= smallest ? 1 / l : 0;
        for (int d = 0; d < 3; ++d)
        {
          expected[static_cast<size_t>(c[k])][static_cast<size_t>(d)] += w * x[d];
        }
      }
    }
    // A copy of point 4 that no polygon uses: something to weld.
    std::vector<normalstest::Vec> withCopy = given;
    withCopy.push_back(given[4]);
    vtkSmartPointer<vtkPolyData> weldable = meshOf(withCopy, polys, type);
    // Without splitting and with it (the triangle block), and with welding
    // too (the per-corner path). At 180 degrees no edge is sharp: points
    // keep their ids.
    for (int path = 0; path < 3; ++path)
    {
      vtkSmartPointer<vtkPolyData> out =
        normalsOf(path == 2 ? weldable : mesh, slPolyDataNormals::MAX, path > 0, 180.0, path == 2);
      ASSERT_EQ(out->GetNumberOfPoints(), path == 2 ? 8 : 7);
      for (vtkIdType i = 0; i < 7; ++i)
      {
        const std::string what = std::string(type == VTK_FLOAT ? "float" : "double") +
          (path == 0 ? "" : path == 1 ? ", split" : ", split, weld") + ", point " + std::to_string(i);
        double n[3];
        out->GetPointData()->GetNormals()->GetTuple(i, n);
        const auto& e = expected[static_cast<size_t>(i)];
        const double reference[3] = { static_cast<double>(e[0]), static_cast<double>(e[1]),
          static_cast<double>(e[2]) };
        if (i == 6)
        {
          EXPECT_TRUE(reference[0] == 0 && reference[1] == 0 && reference[2] == 0) << what;
          EXPECT_TRUE(n[0] == 0 && n[1] == 0 && n[2] == 0) << what << ": " << n[0] << " " << n[1] << " " << n[2];
          continue;
        }
        if (!isUnit(n))
        {
          ADD_FAILURE() << what << ": " << n[0] << " " << n[1] << " " << n[2];
          continue;
        }
        EXPECT_LT(normalstest::angleDegrees(n, reference), 2e-3) << what;
      }
    }
  }
}
