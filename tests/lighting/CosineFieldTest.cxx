// slCosineField: N.L per point and per cell against dot products computed here.
#include "LightingTestMeshes.h"

#include "slCosineField.h"
#include "VTKErrors.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <gtest/gtest.h>

using namespace shadelab;
using namespace shadelab::test;

namespace
{
double value(vtkFieldData* data, const char* name, vtkIdType i)
{
  vtkDataArray* a = data->GetArray(name);
  return a ? a->GetComponent(i, 0) : NAN;
}

/// N.L with L toward @p light from @p p, in double precision.
double cosineToPoint(const double p[3], const double n[3], const glm::vec3& light)
{
  double L[3] = { light.x - p[0], light.y - p[1], light.z - p[2] };
  const double ll = std::sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
  const double nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  return (n[0] * L[0] + n[1] * L[1] + n[2] * L[2]) / (ll * nl);
}
} // namespace

TEST(CosineField, PointLightCosineChangesFromPointToPoint)
{
  SceneLight light = whiteLight(LightType::Point);
  light.position = glm::vec3(0.5f, 2.0f, 0.0f);
  vtkNew<slCosineField> filter;
  filter->SetScene(makeScene({ light }, ShadingModel::Lambert));
  filter->SetLightIndex(0);
  vtkSmartPointer<vtkPolyData> mesh = sphere(16);
  filter->SetInputData(mesh);
  ASSERT_EQ(updateError(filter), "");
  vtkPolyData* out = filter->GetOutput();
  int negative = 0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3], n[3];
    mesh->GetPoint(i, p);
    mesh->GetPointData()->GetNormals()->GetTuple(i, n);
    const double expected = cosineToPoint(p, n, light.position);
    EXPECT_NEAR(value(out->GetPointData(), "CosThetaRaw", i), expected, 1e-5);
    EXPECT_NEAR(value(out->GetPointData(), "CosTheta", i), std::max(0.0, expected), 1e-5);
    negative += expected < -0.1 ? 1 : 0;
  }
  EXPECT_GT(negative, 10) << "the far side of the sphere shadows itself";

  // Cells: the polygon's own normal at its vertex centroid.
  ASSERT_NE(out->GetCellData()->GetArray("CosThetaRaw"), nullptr);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(c, ids);
    ASSERT_EQ(ids->GetNumberOfIds(), 3);
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      mesh->GetPoint(ids->GetId(k), p[k]);
    }
    const double e1[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
    const double e2[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
    const double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0] };
    const double centre[3] = { (p[0][0] + p[1][0] + p[2][0]) / 3, (p[0][1] + p[1][1] + p[2][1]) / 3,
      (p[0][2] + p[1][2] + p[2][2]) / 3 };
    if (std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) < 1e-9)
    {
      continue;
    }
    EXPECT_NEAR(value(out->GetCellData(), "CosThetaRaw", c), cosineToPoint(centre, n, light.position), 1e-4) << c;
  }
}

TEST(CosineField, OneArrayPerLightAndDirectionalIsConstantDirection)
{
  SceneLight a = whiteLight(LightType::Directional);
  a.direction = glm::vec3(0.0f, 0.0f, -2.0f); // from +z
  SceneLight spot = whiteLight(LightType::Spot);
  spot.position = glm::vec3(3.0f, 0.0f, 0.0f);
  spot.direction = glm::vec3(-1.0f, 0.0f, 0.0f);
  vtkNew<slCosineField> filter;
  filter->SetScene(makeScene({ a, spot }, ShadingModel::Lambert));
  vtkSmartPointer<vtkPolyData> mesh = sphere(10);
  filter->SetInputData(mesh);
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  ASSERT_NE(out->GetPointData()->GetArray("CosTheta_0"), nullptr);
  ASSERT_NE(out->GetPointData()->GetArray("CosThetaRaw_1"), nullptr);
  EXPECT_EQ(out->GetPointData()->GetArray("CosTheta"), nullptr);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3], n[3];
    mesh->GetPoint(i, p);
    mesh->GetPointData()->GetNormals()->GetTuple(i, n);
    EXPECT_NEAR(value(out->GetPointData(), "CosThetaRaw_0", i), n[2] / std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 1e-5);
    EXPECT_NEAR(value(out->GetPointData(), "CosThetaRaw_1", i), cosineToPoint(p, n, spot.position), 1e-5);
  }
}

TEST(CosineField, LightIndexOutOfRangeIsAnError)
{
  vtkNew<slCosineField> filter;
  filter->SetScene(makeScene({ whiteLight(LightType::Directional) }, ShadingModel::Lambert));
  filter->SetLightIndex(3);
  filter->SetInputData(sphere(6));
  EXPECT_EQ(updateError(filter), "LightIndex 3 is out of range: the scene has 1 lights");
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(CosineField, TriangleStripCellsTakeTheirTrianglesNormal)
{
  // A flat strip in z = 0 of 4 triangles, turned as strips turn them, under
  // a light straight above: every cell faces it (cos = 1). Newell's method
  // over the strip's points in order gave 0.
  vtkNew<vtkPoints> points;
  for (double x : { 0.0, 1.0, 2.0 })
  {
    points->InsertNextPoint(x, 0, 0);
    points->InsertNextPoint(x, 1, 0);
  }
  vtkNew<vtkCellArray> strips;
  const vtkIdType strip[] = { 0, 1, 2, 3, 4, 5 };
  strips->InsertNextCell(6, strip);
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetStrips(strips);
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < 6; ++i)
  {
    normals->InsertNextTuple3(0, 0, -1); // the strip's triangles (0, 1, 2), (2, 1, 3), ... face -z
  }
  mesh->GetPointData()->SetNormals(normals);
  SceneLight light = whiteLight(LightType::Directional);
  light.direction = glm::vec3(0.0f, 0.0f, 1.0f); // travelling +z: the light is below, at -z
  vtkNew<slCosineField> filter;
  filter->SetScene(makeScene({ light }, ShadingModel::Lambert));
  filter->SetLightIndex(0);
  filter->SetInputData(mesh);
  ASSERT_EQ(updateError(filter), "");
  EXPECT_NEAR(value(filter->GetOutput()->GetCellData(), "CosThetaRaw", 0), 1.0, 1e-6);
  EXPECT_NEAR(value(filter->GetOutput()->GetPointData(), "CosThetaRaw", 3), 1.0, 1e-6);

  // Folded along x = 1 by 90 degrees (the second half stands up, z = x - 1):
  // the area-weighted mean of (0, 0, -1) over area 1 and (1, 0, 0)... of the
  // upright half's normal over area 1: (n1 + n2) / |n1 + n2|, 45 degrees
  // from each, so cos = 1 / sqrt(2) under the same light.
  points->SetPoint(4, 1, 0, 1);
  points->SetPoint(5, 1, 1, 1);
  points->Modified();
  ASSERT_EQ(updateError(filter), "");
  EXPECT_NEAR(value(filter->GetOutput()->GetCellData(), "CosThetaRaw", 0), 1.0 / std::sqrt(2.0), 1e-6);
}
