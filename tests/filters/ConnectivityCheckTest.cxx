// slConnectivityProblem: the one check every filter makes before following
// cell point ids.
#include "slConnectivityCheck.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>

#include <gtest/gtest.h>

#include <vector>

namespace
{
/// Three points and the given polygons (point-id lists).
vtkSmartPointer<vtkPolyData> triangles(const std::vector<std::vector<vtkIdType>>& cells, bool storage64 = true)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  mesh->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  if (!storage64)
  {
    polys->Use32BitStorage();
  }
  for (const auto& ids : cells)
  {
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  mesh->SetPolys(polys);
  return mesh;
}
} // namespace

TEST(ConnectivityCheck, ValidMeshesPass)
{
  EXPECT_EQ(slConnectivityProblem(nullptr), "");
  vtkNew<vtkPolyData> empty;
  EXPECT_EQ(slConnectivityProblem(empty), "");
  EXPECT_EQ(slConnectivityProblem(triangles({ { 0, 1, 2 }, { 2, 1, 0 } })), "");
  EXPECT_EQ(slConnectivityProblem(triangles({ { 0, 1, 2 } }, false)), "");
}

TEST(ConnectivityCheck, NamesTheFirstBadCellAndPoint)
{
  for (bool storage64 : { true, false })
  {
    EXPECT_EQ(slConnectivityProblem(triangles({ { 0, 1, 2 }, { 0, 1, 3 }, { 9, 0, 1 } }, storage64)),
      "polygon 1 names point 3, but the mesh has 3 points (0 to 2)");
    EXPECT_EQ(slConnectivityProblem(triangles({ { 0, 1, 2 }, { 0, 1, 2 }, { 0, -1, 2 } }, storage64)),
      "polygon 2 names point -1, but the mesh has 3 points (0 to 2)");
  }
}

TEST(ConnectivityCheck, FindsTheFirstAmongManyInParallel)
{
  // Enough ids for several parallel ranges; the bad ones late and early in
  // different ranges: the first one is reported whatever the order.
  std::vector<std::vector<vtkIdType>> cells(200000, std::vector<vtkIdType>{ 0, 1, 2 });
  cells[150000][1] = 7;
  cells[70001][2] = 5;
  EXPECT_EQ(slConnectivityProblem(triangles(cells)), "polygon 70001 names point 5, but the mesh has 3 points (0 to 2)");
}

TEST(ConnectivityCheck, EveryCellKind)
{
  vtkSmartPointer<vtkPolyData> mesh = triangles({ { 0, 1, 2 } });
  vtkNew<vtkCellArray> strips, lines, verts;
  const vtkIdType strip[4] = { 0, 1, 2, 4 };
  strips->InsertNextCell(4, strip);
  mesh->SetStrips(strips);
  EXPECT_EQ(slConnectivityProblem(mesh), "strip 0 names point 4, but the mesh has 3 points (0 to 2)");
  mesh->SetStrips(nullptr);
  const vtkIdType line[2] = { 3, 0 };
  lines->InsertNextCell(2, line);
  mesh->SetLines(lines);
  EXPECT_EQ(slConnectivityProblem(mesh), "line 0 names point 3, but the mesh has 3 points (0 to 2)");
  mesh->SetLines(nullptr);
  const vtkIdType vertex = 8;
  verts->InsertNextCell(1, &vertex);
  mesh->SetVerts(verts);
  EXPECT_EQ(slConnectivityProblem(mesh), "vertex cell 0 names point 8, but the mesh has 3 points (0 to 2)");
}

TEST(ConnectivityCheck, CellsWithoutPoints)
{
  vtkSmartPointer<vtkPolyData> mesh = triangles({ { 0, 1, 2 } });
  mesh->SetPoints(nullptr);
  EXPECT_EQ(slConnectivityProblem(mesh), "polygon 0 names point 0, but the mesh has 0 points");
}

TEST(ConnectivityCheck, InconsistentOffsets)
{
  // Offsets set directly, as a VTK user may: beyond the ids, or decreasing.
  vtkSmartPointer<vtkPolyData> mesh = triangles({});
  vtkNew<vtkTypeInt64Array> offsets, ids;
  for (vtkTypeInt64 v : { 0, 1, 2 })
  {
    ids->InsertNextValue(v);
  }
  for (vtkTypeInt64 v : { 0, 5 })
  {
    offsets->InsertNextValue(v);
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, ids);
  mesh->SetPolys(polys);
  EXPECT_EQ(slConnectivityProblem(mesh), "polygon cells: offsets do not span their 3 point ids");

  vtkNew<vtkTypeInt64Array> decreasing;
  for (vtkTypeInt64 v : { 0, 2, 1, 3 })
  {
    decreasing->InsertNextValue(v);
  }
  vtkNew<vtkCellArray> bad;
  bad->SetData(decreasing, ids);
  mesh->SetPolys(bad);
  EXPECT_EQ(slConnectivityProblem(mesh), "polygon 1: its offset decreases");
}

TEST(ConnectivityCheck, ShortPointAndCellArrays)
{
  // Normals of 2 tuples for 3 points made slCosineField read beyond them
  // (a segmentation fault on a large mesh); cell normals too.
  vtkSmartPointer<vtkPolyData> mesh = triangles({ { 0, 1, 2 }, { 2, 1, 0 } });
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(2);
  normals->FillValue(1.0f);
  mesh->GetPointData()->SetNormals(normals);
  EXPECT_EQ(slConnectivityProblem(mesh), "point array \"Normals\" has 2 tuples for 3 points");
  EXPECT_EQ(slConnectivityProblem(mesh, false), "point array \"Normals\" has 2 tuples for 3 points");
  normals->SetNumberOfTuples(4); // longer: read no further than the mesh
  normals->FillValue(1.0f);
  EXPECT_EQ(slConnectivityProblem(mesh), "");

  vtkNew<vtkIntArray> unnamed;
  unnamed->SetNumberOfTuples(1);
  mesh->GetCellData()->AddArray(unnamed);
  EXPECT_EQ(slConnectivityProblem(mesh), "cell array number 0 has 1 tuple for 2 cells");
}
