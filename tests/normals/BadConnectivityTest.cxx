// Every ShadeLab::Normals filter checks its input's cells against its
// points (slConnectivityProblem) before following them: a polydata built in
// memory with a bad point id gives a clear error and an empty output, not a
// read or write outside the per-point arrays.
#include "slBumpMapFilter.h"
#include "slDisplacementFilter.h"
#include "slNormalMapFilter.h"
#include "slPolyDataNormals.h"
#include "slPolyDataTangents.h"
#include "VTKErrors.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace
{
/// A quad as two triangles with UVs and normals, whose second triangle
/// names point @p bad (valid: 0 to 3).
vtkSmartPointer<vtkPolyData> quad(vtkIdType bad)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> uv, normals;
  uv->SetNumberOfComponents(2);
  normals->SetNumberOfComponents(3);
  const double corners[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  for (const auto& c : corners)
  {
    points->InsertNextPoint(c[0], c[1], 0);
    uv->InsertNextTuple2(c[0], c[1]);
    normals->InsertNextTuple3(0, 0, 1);
  }
  vtkNew<vtkCellArray> polys;
  const vtkIdType first[3] = { 0, 1, 2 }, second[3] = { 0, 2, bad };
  polys->InsertNextCell(3, first);
  polys->InsertNextCell(3, second);
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  mesh->GetPointData()->SetTCoords(uv);
  mesh->GetPointData()->SetNormals(normals);
  return mesh;
}

template <typename Filter>
void expectRejected(vtkIdType bad, const std::string& message)
{
  vtkNew<Filter> filter;
  filter->SetInputData(quad(bad));
  EXPECT_EQ(updateError(filter), message);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfCells(), 0);
}

template <typename Filter>
void expectDetailRejected(vtkIdType bad, const std::string& message)
{
  vtkNew<Filter> filter;
  filter->SetFileName("no-image-needed.png");
  filter->SetInputData(quad(bad));
  EXPECT_EQ(updateError(filter), message);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
}
} // namespace

TEST(BadConnectivity, ValidQuadIsAccepted)
{
  vtkNew<slPolyDataNormals> normals;
  normals->SetInputData(quad(3));
  EXPECT_EQ(updateError(normals), "");
  EXPECT_EQ(normals->GetOutput()->GetNumberOfPolys(), 2);
}

TEST(BadConnectivity, EveryNormalsFilterRejectsAPointBeyondTheMesh)
{
  const std::string beyond = "polygon 1 names point 4, but the mesh has 4 points (0 to 3)";
  expectRejected<slPolyDataNormals>(4, beyond);
  expectRejected<slPolyDataTangents>(4, beyond);
  expectDetailRejected<slNormalMapFilter>(4, beyond);
  expectDetailRejected<slBumpMapFilter>(4, beyond);
  expectDetailRejected<slDisplacementFilter>(4, beyond);
}

TEST(BadConnectivity, NegativeAndHugeIds)
{
  expectRejected<slPolyDataNormals>(-1, "polygon 1 names point -1, but the mesh has 4 points (0 to 3)");
  expectRejected<slPolyDataTangents>(
    vtkIdType(1) << 40, "polygon 1 names point 1099511627776, but the mesh has 4 points (0 to 3)");
}

namespace
{
/// A jittered grid of n x n cells, each two triangles or, where (i + j) % 53
/// is 0, a quad; polygons in random order when @p shuffled (the normals then
/// take their path for meshes without locality, which prefetches points).
vtkSmartPointer<vtkPolyData> grid(int n, bool shuffled)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  vtkNew<vtkPoints> points;
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      points->InsertNextPoint(i + jitter(rng), j + jitter(rng), jitter(rng));
    }
  }
  std::vector<std::vector<vtkIdType>> polygons;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const vtkIdType a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      if ((i + j) % 53 == 0)
      {
        polygons.push_back({ a, b, c, d });
        continue;
      }
      polygons.push_back({ a, b, c });
      polygons.push_back({ a, c, d });
    }
  }
  if (shuffled)
  {
    std::shuffle(polygons.begin(), polygons.end(), rng);
  }
  vtkNew<vtkCellArray> cells;
  for (const auto& p : polygons)
  {
    cells->InsertNextCell(static_cast<vtkIdType>(p.size()), p.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(cells);
  return mesh;
}

/// Sets the second point id of polygon @p polygon of @p mesh to @p id.
void setSecondId(vtkPolyData* mesh, vtkIdType polygon, vtkIdType id)
{
  vtkCellArray* cells = mesh->GetPolys();
  const vtkIdType at = cells->GetOffsetsArray()->GetComponent(polygon, 0) + 1;
  cells->GetConnectivityArray()->SetComponent(at, 0, static_cast<double>(id));
}

/// The first polygon at or after @p from with @p corners corners.
vtkIdType firstWith(vtkPolyData* mesh, vtkIdType from, vtkIdType corners)
{
  for (vtkIdType c = from; c < mesh->GetNumberOfPolys(); ++c)
  {
    if (mesh->GetPolys()->GetCellSize(c) == corners)
    {
      return c;
    }
  }
  return -1;
}
} // namespace

// The plain vertex-normal path checks polygon ids as it reads them instead of
// in a pass of their own; every path must still name the first bad polygon,
// in a triangle or another polygon, on a small mesh and on one cut into
// chunks (ordered and in random order), and leave an empty output.
TEST(BadConnectivity, NormalsOnEveryPathNameTheFirstBadPolygon)
{
  struct Path
  {
    const char* name;
    bool split, consistency, weld, pointNormals, cellNormals;
  };
  const Path paths[] = {
    { "defaults", true, true, false, true, false },
    { "no split, no consistency", false, false, false, true, false },
    { "no split, no consistency, cell normals", false, false, false, true, true },
    { "cell normals only", false, false, false, false, true },
    { "consistency only", false, true, false, true, false },
    { "welding", false, false, true, true, false },
  };
  for (const bool shuffled : { false, true })
  {
    // 190^2 cells: about 72,000 polygons, more than one chunk.
    const vtkSmartPointer<vtkPolyData> clean = grid(190, shuffled);
    const vtkIdType numPoints = clean->GetNumberOfPoints();
    const std::string points =
      ", but the mesh has " + std::to_string(numPoints) + " points (0 to " + std::to_string(numPoints - 1) + ")";
    for (const vtkIdType corners : { 3, 4 })
    {
      const vtkIdType polygon = firstWith(clean, 50000, corners);
      ASSERT_GE(polygon, 0);
      for (const vtkIdType bad : { numPoints, vtkIdType(-1), vtkIdType(1) << 40 })
      {
        auto mesh = vtkSmartPointer<vtkPolyData>::New();
        mesh->DeepCopy(clean);
        setSecondId(mesh, polygon, bad);
        setSecondId(mesh, polygon + 3000, numPoints + 5); // a later bad polygon is not the one named
        const std::string expected = "polygon " + std::to_string(polygon) + " names point " + std::to_string(bad) + points;
        for (const Path& path : paths)
        {
          vtkNew<slPolyDataNormals> normals;
          normals->SetInputData(mesh);
          normals->SetSplitting(path.split);
          normals->SetConsistency(path.consistency);
          normals->SetWeldCoincidentPoints(path.weld);
          normals->SetComputePointNormals(path.pointNormals);
          normals->SetComputeCellNormals(path.cellNormals);
          const std::string what = std::string(path.name) + (shuffled ? ", shuffled" : ", ordered") + ", " +
            std::to_string(corners) + "-gon, id " + std::to_string(bad);
          EXPECT_EQ(updateError(normals), expected) << what;
          EXPECT_EQ(normals->GetOutput()->GetNumberOfPoints(), 0) << what;
        }
      }
    }
  }
}
