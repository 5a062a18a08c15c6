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
