// BRDF lobes and directional albedo against closed forms and independent quadrature.
#include "LightingTestMeshes.h"

#include "shadelab/Albedo.h"

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
#include <string>

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

TEST(AlbedoTable, MaterialNumbersReachTheTable)
{
  // Rougher GGX: the same column as the core's directional albedo at that roughness.
  vtkNew<slAlbedoTable> table;
  table->SetNumberOfAngles(3);
  ASSERT_TRUE(table->SetMaterialParameter("roughness", 0.8));
  table->Update();
  glsl::slMaterial m = toEvaluationMaterial(SceneMaterial()); // the table's defaults (ior 1.5)
  m.ambient = m.diffuse = m.emission = glm::vec3(0.0f);
  m.specular = glm::vec3(1.0f);
  m.roughness = 0.8f;
  const int ggx = static_cast<int>(ShadingModel::CookTorranceGGX);
  for (int row = 0; row < 3; ++row)
  {
    const double theta = column(table->GetOutput(), "IncidenceDegrees", row) * kPi / 180.0;
    EXPECT_NEAR(column(table->GetOutput(), "cook-torrance-ggx", row), directionalAlbedo(ggx, m, theta), 1e-12) << row;
  }
  glsl::slMaterial smoother = m;
  smoother.roughness = 0.3f; // the table's default: the parameter did make a difference
  EXPECT_GT(std::abs(directionalAlbedo(ggx, m, 0.0) - directionalAlbedo(ggx, smoother, 0.0)), 1e-3);
}

TEST(AlbedoTable, ClosedFormsAtTheMaterialsRoughnessAndIndex)
{
  vtkNew<slAlbedoTable> table;
  table->SetNumberOfAngles(4);
  table->SetMaterialParameter("roughness", 5.0);
  table->SetMaterialParameter("ior", 0.5);
  EXPECT_EQ(table->GetMaterialParameter("roughness"), 1.0);
  EXPECT_EQ(table->GetMaterialParameter("ior"), 1.0);
  table->SetMaterialParameter("ior", 10.0);
  table->Update();
  // GGX at roughness 1 and normal incidence: D = 1 / pi, G2 = 2 c / (1 + c)
  // at cos(theta_o) = c, V.H = sqrt((1 + c) / 2), so a = integral over [0, 1]
  // of F(V.H) c / (1 + c) dc with Schlick's F, F0 = (9 / 11)^2.
  const double f0 = std::pow(9.0 / 11.0, 2.0);
  const int steps = 20000;
  double expected = 0.0;
  for (int i = 0; i < steps; ++i)
  {
    const double c = (i + 0.5) / steps, vh = std::sqrt(0.5 * (1.0 + c));
    expected += (f0 + (1.0 - f0) * std::pow(1.0 - vh, 5.0)) * c / (1.0 + c) / steps;
  }
  EXPECT_NEAR(column(table->GetOutput(), "cook-torrance-ggx", 0), expected, 1e-6);
  // Oren-Nayar at roughness 0 is the normalised Lambert: 1 at every angle.
  table->SetMaterialParameter("roughness", 0.0);
  table->Update();
  for (int row = 0; row < 4; ++row)
  {
    EXPECT_NEAR(column(table->GetOutput(), "oren-nayar", row), 1.0, 1e-6) << row;
  }
  // Ward's pair: swapping X and Y leaves normal incidence alone and changes
  // an incidence in the plane of X.
  table->SetMaterialParameter("roughnessX", 0.1);
  table->SetMaterialParameter("roughnessY", 0.6);
  table->Update();
  const double normal = column(table->GetOutput(), "ward", 0), oblique = column(table->GetOutput(), "ward", 2);
  table->SetMaterialParameter("roughnessX", 0.6);
  table->SetMaterialParameter("roughnessY", 0.1);
  table->Update();
  EXPECT_NEAR(column(table->GetOutput(), "ward", 0), normal, 1e-6);
  EXPECT_GT(std::abs(column(table->GetOutput(), "ward", 2) - oblique), 1e-3);
}

TEST(AlbedoTable, OnlyTheEnabledModelsHaveColumns)
{
  vtkNew<slAlbedoTable> table;
  table->SetNumberOfAngles(3);
  table->SetShininess(20.0);
  table->DisableAllModels();
  const int phong = static_cast<int>(ShadingModel::Phong), ward = static_cast<int>(ShadingModel::Ward);
  // Enabled out of order: the columns stay in model order, each under its name.
  EXPECT_TRUE(table->SetModelEnabled("ward", true));
  EXPECT_TRUE(table->SetModelEnabled(phong, true));
  table->Update();
  vtkTable* t = table->GetOutput();
  ASSERT_EQ(t->GetNumberOfColumns(), 3);
  EXPECT_STREQ(t->GetColumnName(0), "IncidenceDegrees");
  EXPECT_STREQ(t->GetColumnName(1), "phong");
  EXPECT_STREQ(t->GetColumnName(2), "ward");
  // Lecture Phong at normal incidence: 2 pi / (n + 2); Ward's column holds
  // Ward's values (those of the table of every model).
  EXPECT_NEAR(column(t, "phong", 0), 2.0 * kPi / 22.0, 1e-6);
  vtkNew<slAlbedoTable> every;
  every->SetNumberOfAngles(3);
  every->Update();
  EXPECT_EQ(every->GetOutput()->GetNumberOfColumns(), 1 + kLightingModelCount);
  for (int row = 0; row < 3; ++row)
  {
    EXPECT_EQ(column(t, "ward", row), column(every->GetOutput(), "ward", row)) << row;
  }
  // A change of the selection updates the table.
  EXPECT_TRUE(table->SetModelEnabled(ward, false));
  EXPECT_FALSE(table->GetModelEnabled(ward));
  EXPECT_TRUE(table->GetModelEnabled(phong));
  table->Update();
  EXPECT_EQ(table->GetOutput()->GetNumberOfColumns(), 2);
  table->EnableAllModels();
  table->Update();
  EXPECT_EQ(table->GetOutput()->GetNumberOfColumns(), 1 + kLightingModelCount);
  // No such model: an error, and nothing changes.
  std::string error = callError(table, [&] { return table->SetModelEnabled(kLightingModelCount, false); });
  EXPECT_NE(error.find("SetModelEnabled: 11 is not a lighting model (0 lambert, 1 phong,"), std::string::npos)
    << error;
  error = callError(table, [&] { return table->SetModelEnabled("toon", false); });
  EXPECT_NE(error.find("SetModelEnabled: \"toon\" is not a lighting model (lambert, phong,"), std::string::npos)
    << error;
  EXPECT_FALSE(table->GetModelEnabled(-1));
  EXPECT_TRUE(table->GetModelEnabled(kLightingModelCount - 1));
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

TEST(BRDFLobeSource, WeightsNotGivenShowTheModelsOwnTerm)
{
  // Without weights a lobe is never empty: Lambert's is its diffuse
  // hemisphere (k_d = 1: radius 1, normalised 1/pi, Oren-Nayar above 0),
  // Phong's its specular lobe alone (k_d = 0, k_s = 1: 1 / cos 30 at the
  // mirror direction, where max(0, R.V)^n = 1).
  const auto radii = [](int model) {
    vtkNew<slBRDFLobeSource> lobe;
    lobe->SetModel(model);
    lobe->SetIncidenceAngle(30.0);
    lobe->Update();
    vtkPolyData* surface = lobe->GetOutput(0);
    double lo = INFINITY, hi = 0.0;
    for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
    {
      double p[3];
      surface->GetPoint(i, p);
      const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      lo = std::min(lo, r);
      hi = std::max(hi, r);
    }
    return std::make_pair(lo, hi);
  };
  EXPECT_NEAR(radii(0).first, 1.0, 1e-6);
  EXPECT_NEAR(radii(0).second, 1.0, 1e-6);
  EXPECT_NEAR(radii(3).first, 1.0 / kPi, 1e-6);
  EXPECT_NEAR(radii(3).second, 1.0 / kPi, 1e-6);
  EXPECT_GT(radii(8).first, 0.1 / kPi); // oren-nayar: rough Lambert
  const std::pair<double, double> phong = radii(1);
  EXPECT_NEAR(phong.second, 1.0 / std::cos(30.0 * kPi / 180.0), 0.02); // sampled near the peak
  EXPECT_NEAR(phong.first, 0.0, 1e-6);

  // A weight given is used as given, the other still the model's.
  vtkNew<slBRDFLobeSource> lobe;
  lobe->SetModel(0);
  lobe->SetSpecularWeight(5.0);
  lobe->Update();
  double p[3];
  lobe->GetOutput(0)->GetPoint(0, p);
  EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.0, 1e-6);
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

TEST(BRDFLobeSource, MaterialNumbersReachTheLobe)
{
  // GGX at normal incidence, seen along the normal: D = 1 / (pi a^2), the
  // height-correlated G2 / (4 ci co) = 1/4, F = F0 = ((ior - 1) / (ior + 1))^2.
  vtkNew<slBRDFLobeSource> lobe;
  lobe->SetModel(static_cast<int>(ShadingModel::CookTorranceGGX));
  lobe->SetIncidenceAngle(0.0);
  for (double a : { 0.2, 0.5 })
  {
    EXPECT_TRUE(lobe->SetMaterialParameter("roughness", a));
    EXPECT_TRUE(lobe->SetMaterialParameter("ior", 2.0));
    lobe->Update();
    const double f0 = (1.0 / 3.0) * (1.0 / 3.0);
    EXPECT_NEAR(lobe->GetOutput(0)->GetPointData()->GetScalars()->GetTuple1(0), f0 / (4.0 * kPi * a * a), 1e-5) << a;
  }
  // Out of range: clamped to the scene format's range; unknown keys: an error.
  lobe->SetMaterialParameter("roughness", 3.0);
  EXPECT_EQ(lobe->GetMaterialParameter("roughness"), 1.0);
  std::string error = callError(lobe, [&] { return lobe->SetMaterialParameter("gloss", 1.0); });
  EXPECT_NE(error.find("\"gloss\" is not a number of the material (shininess, roughness"), std::string::npos) << error;
  error = callError(lobe, [&] { return lobe->SetMaterialParameter("diffuse", 1.0); });
  EXPECT_NE(error.find("\"diffuse\" is not a number"), std::string::npos) << error;
  error = callError(lobe, [&] { return lobe->SetMaterialParameter("ior", NAN); });
  EXPECT_NE(error.find("ior: NaN"), std::string::npos) << error;
  EXPECT_EQ(lobe->GetMaterialParameter("ior"), 2.0);
}

TEST(BRDFLobeSource, WardLobeFollowsTheRoughnessPair)
{
  // Ward at normal incidence (L = N = +z), tangent X = +x, written in the
  // half vector's angles: f = exp(-tan^2(d) (cos^2(p) / ax^2 + sin^2(p) / ay^2))
  // / (4 pi ax ay sqrt(cos theta_o)), d the half vector's polar angle and p its azimuth.
  const double ax = 0.1, ay = 0.4;
  vtkNew<slBRDFLobeSource> lobe;
  lobe->SetModel(static_cast<int>(ShadingModel::Ward));
  lobe->SetIncidenceAngle(0.0);
  lobe->SetMaterialParameter("roughnessX", ax);
  lobe->SetMaterialParameter("roughnessY", ay);
  lobe->Update();
  vtkPolyData* surface = lobe->GetOutput(0);
  vtkDataArray* r = surface->GetPointData()->GetScalars();
  int checked = 0;
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double p[3];
    surface->GetPoint(i, p);
    const double length = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    if (length < 1e-3 || p[2] < 0.05 * length)
    {
      continue; // too small to have a direction, or grazing
    }
    const double thetaO = std::acos(p[2] / length), phi = std::atan2(p[1], p[0]);
    const double d = 0.5 * thetaO, t2 = std::tan(d) * std::tan(d);
    const double c = std::cos(phi), s = std::sin(phi);
    const double f =
      std::exp(-t2 * (c * c / (ax * ax) + s * s / (ay * ay))) / (4.0 * kPi * ax * ay * std::sqrt(std::cos(thetaO)));
    EXPECT_NEAR(r->GetTuple1(i), f, 1e-4 * f + 1e-6) << i;
    ++checked;
  }
  EXPECT_GT(checked, 100);

  // There is no plane of incidence at normal incidence; the slice stays in
  // the x-z plane, the limit as the light leaves the normal, so it follows
  // roughnessX there as at every other angle: along +x the half vector is at
  // theta_o / 2 and f = exp(-tan^2(theta_o / 2) / ax^2) / (4 pi ax ay sqrt(cos theta_o)).
  vtkPolyData* slice = lobe->GetSliceOutput();
  vtkDataArray* sliceR = slice->GetPointData()->GetScalars();
  int sliceChecked = 0;
  for (vtkIdType i = 0; i < slice->GetNumberOfPoints(); ++i)
  {
    double p[3];
    slice->GetPoint(i, p);
    EXPECT_NEAR(p[1], 0.0, 1e-7) << i;
    const double length = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    if (length < 1e-3 || p[2] < 0.05 * length)
    {
      continue; // too small to have a direction, or grazing
    }
    const double thetaO = std::acos(p[2] / length), t = std::tan(0.5 * thetaO);
    const double f = std::exp(-t * t / (ax * ax)) / (4.0 * kPi * ax * ay * std::sqrt(std::cos(thetaO)));
    EXPECT_NEAR(sliceR->GetTuple1(i), f, 1e-4 * f + 1e-6) << i;
    ++sliceChecked;
  }
  EXPECT_GT(sliceChecked, 20);
}

TEST(LobesOnMesh, AnAmbientLightIsRefused)
{
  // An ambient light gives no incident direction: the chosen light is an
  // error, not an empty output that blames the points for facing away.
  SceneLight ambient = whiteLight(LightType::Ambient);
  ambient.ambient = glm::vec3(1.0f);
  SceneLight key = whiteLight(LightType::Directional);
  key.direction = glm::vec3(0.0f, 0.0f, -1.0f);
  vtkNew<slLobesOnMesh> lobes;
  lobes->SetScene(makeScene({ ambient, key }, ShadingModel::BlinnPhong));
  lobes->SetInputData(sphere(12));
  lobes->SetLightIndex(0);
  EXPECT_EQ(updateError(lobes),
    "LightIndex 0: the light is ambient; a lobe needs an incident direction (a directional, point or spot light)");
  // The default takes the first light with a direction.
  lobes->SetLightIndex(-1);
  ASSERT_EQ(updateError(lobes), "");
  EXPECT_EQ(lobes->GetNumberOfLobesDrawn(), 16);
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

TEST(BRDFLobeSource, GivenBRDFValuesMakeTheLobe)
{
  // f_r given per direction (as the GPU gives a .brdf file's): a constant
  // (0.1, 0.2, 0.3) is a hemisphere of radius 0.2, times cos(theta_o) with
  // the cosine factor; the model's settings no longer matter.
  for (bool cosine : { false, true })
  {
    vtkNew<slBRDFLobeSource> lobe;
    lobe->SetModel(1);
    lobe->SetIncidenceAngle(50.0);
    lobe->SetMultiplyByCosine(cosine);
    vtkNew<vtkFloatArray> surface, slice;
    lobe->ComputeOutgoingDirections(surface, slice);
    auto constant = [](vtkFloatArray* directions) {
      auto values = vtkSmartPointer<vtkFloatArray>::New();
      values->SetNumberOfComponents(3);
      for (vtkIdType k = 0; k < directions->GetNumberOfTuples(); ++k)
      {
        values->InsertNextTuple3(0.1, 0.2, 0.3);
      }
      return values;
    };
    lobe->SetBRDFValues(constant(surface), constant(slice));
    ASSERT_EQ(updateError(lobe), "");
    for (int port : { 0, 1 })
    {
      vtkPolyData* output = lobe->GetOutput(port);
      vtkFloatArray* directions = port == 0 ? surface.Get() : slice.Get();
      ASSERT_EQ(output->GetNumberOfPoints(), directions->GetNumberOfTuples());
      for (vtkIdType k = 0; k < output->GetNumberOfPoints(); ++k)
      {
        double p[3], d[3];
        output->GetPoint(k, p);
        directions->GetTuple(k, d);
        const double r = cosine ? 0.2 * std::max(0.0, d[2]) : 0.2;
        for (int c = 0; c < 3; ++c)
        {
          EXPECT_NEAR(p[c], r * d[c], 1e-6) << port << " " << k;
        }
      }
    }
  }
  // Every direction is a unit vector on the upper hemisphere.
  vtkNew<slBRDFLobeSource> lobe;
  vtkNew<vtkFloatArray> surface, slice;
  lobe->ComputeOutgoingDirections(surface, slice);
  EXPECT_EQ(surface->GetNumberOfTuples(), 1 + 32 * 64);
  EXPECT_EQ(slice->GetNumberOfTuples(), 2 * 32 * 4 + 1);
  for (vtkIdType k = 0; k < surface->GetNumberOfTuples(); ++k)
  {
    double d[3];
    surface->GetTuple(k, d);
    EXPECT_NEAR(d[0] * d[0] + d[1] * d[1] + d[2] * d[2], 1.0, 1e-6);
    EXPECT_GE(d[2], -1e-6);
  }
}

TEST(BRDFLobeSource, BRDFValuesOfTheWrongSizeAreAnError)
{
  vtkNew<slBRDFLobeSource> lobe;
  vtkNew<vtkFloatArray> surface, slice;
  lobe->ComputeOutgoingDirections(surface, slice);
  vtkNew<vtkFloatArray> shortSurface;
  shortSurface->SetNumberOfComponents(3);
  shortSurface->SetNumberOfTuples(5);
  lobe->SetBRDFValues(shortSurface, slice);
  EXPECT_EQ(updateError(lobe), "the surface BRDF values hold 5 tuples of 3 components; the lobe has 2049 directions "
                               "(3 components each)");
  EXPECT_EQ(lobe->GetOutput(0)->GetNumberOfPoints(), 0);
  lobe->SetBRDFValues(surface, nullptr);
  EXPECT_EQ(updateError(lobe), "SetBRDFValues needs both arrays, the surface's and the slice's");
  lobe->SetBRDFValues(nullptr, nullptr);
  EXPECT_EQ(updateError(lobe), "");
  EXPECT_GT(lobe->GetOutput(0)->GetNumberOfPoints(), 0);
}
