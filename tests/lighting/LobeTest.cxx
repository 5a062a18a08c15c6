// BRDF lobes and directional albedo against closed forms and independent quadrature.
#include "LightingTestMeshes.h"

#include "slAlbedoTable.h"
#include "slBRDFLobeSource.h"
#include "slLobesOnMesh.h"
#include "VTKErrors.h"

#include <vtkIdList.h>
#include <vtkTable.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

using namespace shadelab;
using namespace shadelab::test;

namespace
{
double column(vtkTable* t, const char* name, int row)
{
  vtkAbstractArray* a = t->GetColumnByName(name);
  return a ? a->GetVariantValue(row).ToDouble() : NAN;
}

/// Lecture Blinn-Phong specular albedo at normal incidence, k_s = 1:
/// 2 pi * integral_0^{pi/2} cos^n(theta/2) cos(theta) sin(theta) d theta (N.H = cos(theta/2)).
double lectureBlinnPhongAtNormalIncidence(double n)
{
  const int steps = 20000;
  double sum = 0.0;
  for (int i = 0; i < steps; ++i)
  {
    const double t = (i + 0.5) * 0.5 * kPi / steps;
    sum += std::pow(std::cos(0.5 * t), n) * std::cos(t) * std::sin(t);
  }
  return 2.0 * kPi * sum * 0.5 * kPi / steps;
}
} // namespace

TEST(AlbedoTable, MatchesClosedFormsAndNormalisedModelsStayAtMostOne)
{
  vtkNew<slAlbedoTable> table;
  table->SetShininess(20.0);
  table->SetNumberOfAngles(9);
  table->Update();
  vtkTable* t = table->GetOutput();
  ASSERT_EQ(t->GetNumberOfRows(), 9);
  EXPECT_DOUBLE_EQ(column(t, "IncidenceDegrees", 8), 89.0);
  for (int row = 0; row < 9; ++row)
  {
    EXPECT_NEAR(column(t, "lambert", row), kPi, 1e-6) << row;
    EXPECT_NEAR(column(t, "lambert-normalized", row), 1.0, 1e-6) << row;
    EXPECT_LE(column(t, "phong-normalized", row), 1.0 + 1e-6) << row;
    EXPECT_LE(column(t, "blinn-phong-normalized", row), 1.0 + 1e-6) << row;
  }
  // Normal incidence: normalised Phong and Blinn-Phong reflect exactly 1;
  // lecture Phong 2 pi / (n + 2), lecture Blinn-Phong by quadrature here.
  EXPECT_NEAR(column(t, "phong-normalized", 0), 1.0, 1e-6);
  EXPECT_NEAR(column(t, "blinn-phong-normalized", 0), 1.0, 1e-6);
  EXPECT_NEAR(column(t, "phong", 0), 2.0 * kPi / 22.0, 1e-6);
  EXPECT_NEAR(column(t, "blinn-phong", 0), lectureBlinnPhongAtNormalIncidence(20.0), 1e-6);
  // Lecture Phong gains energy toward grazing incidence (f_r has 1/cos theta_i).
  EXPECT_GT(column(t, "phong", 8), 3.0 * column(t, "phong", 0));
}

TEST(BRDFLobeSource, NormalisedLambertIsAHemisphereOfRadiusRhoOverPi)
{
  vtkNew<slBRDFLobeSource> lobe;
  lobe->SetModel(3);
  lobe->SetDiffuseWeight(0.5);
  lobe->SetIncidenceAngle(30.0);
  lobe->Update();
  vtkPolyData* surface = lobe->GetOutput(0);
  ASSERT_GT(surface->GetNumberOfPoints(), 100);
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double p[3];
    surface->GetPoint(i, p);
    EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 0.5 / kPi, 1e-6);
    EXPECT_GE(p[2], -1e-7);
  }
}

TEST(BRDFLobeSource, PhongSlicePeaksAtTheMirrorDirection)
{
  // Lecture Phong, k_s = 1: f_r = max(0, R.V)^n / cos(theta_i), largest at V = R.
  vtkNew<slBRDFLobeSource> lobe;
  lobe->SetModel(1);
  lobe->SetShininess(50.0);
  lobe->SetIncidenceAngle(60.0);
  lobe->Update();
  vtkPolyData* slice = lobe->GetSliceOutput();
  ASSERT_EQ(slice->GetNumberOfLines(), 1);
  vtkDataArray* r = slice->GetPointData()->GetScalars();
  vtkIdType best = 0;
  for (vtkIdType i = 0; i < r->GetNumberOfTuples(); ++i)
  {
    best = r->GetTuple1(i) > r->GetTuple1(best) ? i : best;
  }
  EXPECT_NEAR(r->GetTuple1(best), 1.0 / std::cos(60.0 * kPi / 180.0), 0.02);
  double p[3];
  slice->GetPoint(best, p);
  EXPECT_NEAR(std::atan2(p[0], p[2]) * 180.0 / kPi, 60.0, 1.5) << "mirror side: +x";
}

TEST(BRDFLobeSource, ShininessTakesTheSceneFormatsRange)
{
  // A scene may hold shininess up to 1e5 (scene.schema.json); the lobe
  // source must draw every such material, and nothing beyond.
  vtkNew<slBRDFLobeSource> lobe;
  lobe->SetShininess(5.0e4);
  EXPECT_EQ(lobe->GetShininess(), 5.0e4);
  lobe->SetShininess(2.0e5);
  EXPECT_EQ(lobe->GetShininess(), 1.0e5);
  lobe->SetShininess(-1.0);
  EXPECT_EQ(lobe->GetShininess(), 0.0);
}

TEST(LobesOnMesh, EachLobeSitsInItsPointsNormalFrame)
{
  SceneLight light = whiteLight(LightType::Point);
  light.position = glm::vec3(0.0f, 0.0f, 3.0f);
  vtkSmartPointer<vtkPolyData> mesh = sphere(12);
  vtkNew<vtkIdList> ids;
  for (vtkIdType id : { vtkIdType(0), vtkIdType(20), vtkIdType(50), mesh->GetNumberOfPoints() - 1 })
  {
    ids->InsertNextId(id);
  }
  vtkNew<slLobesOnMesh> lobes;
  lobes->SetScene(makeScene({ light }, ShadingModel::LambertNormalized));
  lobes->SetPointIds(ids);
  lobes->SetInputData(mesh);
  ASSERT_EQ(updateError(lobes), "");
  vtkPolyData* out = lobes->GetOutput();
  vtkDataArray* owner = out->GetPointData()->GetArray("PointId");
  ASSERT_NE(owner, nullptr);
  ASSERT_GT(out->GetNumberOfPoints(), 0);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    const vtkIdType id = static_cast<vtkIdType>(owner->GetTuple1(i));
    ASSERT_GE(ids->IsId(id), 0);
    double p[3], q[3], n[3];
    mesh->GetPoint(id, p);
    out->GetPoint(i, q);
    mesh->GetPointData()->GetNormals()->GetTuple(id, n);
    const double d[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
    EXPECT_GE(d[0] * n[0] + d[1] * n[1] + d[2] * n[2], -1e-5) << "lobe stays above its tangent plane";
  }
  // The last point (the sphere's bottom) faces away from the light: no lobe.
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    if (owner->GetTuple1(i) == mesh->GetNumberOfPoints() - 1)
    {
      EXPECT_EQ(out->GetPointData()->GetScalars()->GetTuple1(i), 0.0);
    }
  }
}

TEST(LobesOnMesh, SampledPointsAreLitSoEveryLobeShows)
{
  // A directional light from +z lights the upper half of the sphere: the 36
  // sampled points are all lit ones, each with a lobe of non-zero size.
  SceneLight light = whiteLight(LightType::Directional);
  light.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  vtkSmartPointer<vtkPolyData> mesh = sphere(24);
  vtkNew<slLobesOnMesh> lobes;
  lobes->SetScene(makeScene({ light }, ShadingModel::BlinnPhong));
  lobes->SetNumberOfLobes(36);
  lobes->SetInputData(mesh);
  ASSERT_EQ(updateError(lobes), "");
  EXPECT_EQ(lobes->GetNumberOfLobesDrawn(), 36);
  vtkPolyData* out = lobes->GetOutput();
  vtkDataArray* owner = out->GetPointData()->GetArray("PointId");
  std::map<vtkIdType, double> largest; // per lobe: its largest r
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    const vtkIdType id = static_cast<vtkIdType>(owner->GetTuple1(i));
    largest[id] = std::max(largest[id], out->GetPointData()->GetScalars()->GetTuple1(i));
  }
  EXPECT_EQ(largest.size(), 36u);
  for (const auto& lobe : largest)
  {
    double n[3];
    mesh->GetPointData()->GetNormals()->GetTuple(lobe.first, n);
    EXPECT_GT(n[2], 0.0) << "point " << lobe.first << " faces away from the light";
    EXPECT_GT(lobe.second, 0.0) << "point " << lobe.first;
  }

  // Asking for more lobes than there are lit points draws one per lit point.
  vtkIdType litPoints = 0;
  for (vtkIdType id = 0; id < mesh->GetNumberOfPoints(); ++id)
  {
    double n[3];
    mesh->GetPointData()->GetNormals()->GetTuple(id, n);
    litPoints += n[2] / std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) > 1e-6;
  }
  lobes->SetNumberOfLobes(100000);
  lobes->Update();
  EXPECT_EQ(lobes->GetNumberOfLobesDrawn(), litPoints);
  EXPECT_LT(litPoints, mesh->GetNumberOfPoints());
}

TEST(LobesOnMesh, TinyLobesAndPointsThatAreNotFinite)
{
  // A material so dark that the largest BRDF value is below float's normal
  // range (k_d = 1e-40): the lobes are still scaled to the mesh, not to
  // infinity. A chosen point with a NaN coordinate is a one-line error.
  SceneLight light = whiteLight(LightType::Point);
  light.position = glm::vec3(0.0f, 0.0f, 3.0f);
  vtkSmartPointer<slScene> scene = makeScene({ light }, ShadingModel::Lambert);
  Scene s = scene->GetScene();
  s.material.diffuse = glm::vec3(1e-40f);
  scene->SetScene(s);
  vtkSmartPointer<vtkPolyData> mesh = sphere(12);
  vtkNew<slLobesOnMesh> lobes;
  lobes->SetScene(scene);
  lobes->SetInputData(mesh);
  ASSERT_EQ(updateError(lobes), "");
  vtkPolyData* out = lobes->GetOutput();
  ASSERT_GT(out->GetNumberOfPoints(), 0);
  double furthest = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double q[3];
    out->GetPoint(i, q);
    ASSERT_TRUE(std::isfinite(q[0]) && std::isfinite(q[1]) && std::isfinite(q[2])) << i;
    furthest = std::max(furthest, std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]));
  }
  // Lambert lobes are hemispheres; the largest reaches Scale x the mesh's
  // size beyond the unit sphere, as for any material.
  EXPECT_NEAR(furthest, 1.0 + lobes->GetScale() * mesh->GetLength(), 1e-5);

  mesh->GetPoints()->SetPoint(0, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  vtkNew<vtkIdList> ids;
  ids->InsertNextId(0);
  lobes->SetPointIds(ids);
  lobes->SetInputData(mesh);
  EXPECT_EQ(updateError(lobes), "input mesh: point 0 has a coordinate that is not finite");
}
