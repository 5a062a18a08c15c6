// The one camera rule (shadelab::placeCamera through slScene::ApplyCamera):
// a fitted camera keeps the whole mesh in view for every aspect ratio, and
// turns the way VTK's own vtkCamera::Azimuth/Elevation turn.
#include "shadelab/CameraPlacement.h"
#include "shadelab/Scene.h"
#include "slScene.h"

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace
{
struct Size
{
  int width, height;
};
const Size kSizes[] = { { 120, 400 }, { 400, 120 }, { 256, 256 } };

/// Normalised device coordinates (-1..1 across the image) of a world point.
std::array<double, 3> project(vtkCamera* camera, double aspect, const double p[3])
{
  vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0);
  const double in[4] = { p[0], p[1], p[2], 1.0 };
  double out[4];
  m->MultiplyPoint(in, out);
  return { out[0] / out[3], out[1] / out[3], out[2] / out[3] };
}
} // namespace

TEST(CameraPlacement, FittedMeshCornersInsideEveryAspectRatio)
{
  // An off-centre, elongated box: each of its corners must project inside
  // the image (DistanceFillsTheNarrowerDirection checks that the fit is tight).
  const double bounds[6] = { -0.3, 2.1, 0.5, 1.1, -4.0, -3.2 };
  const float turns[][2] = { { 0, 0 }, { 140, 12 }, { -60, 45 }, { 30, -80 }, { 200, 89 } };
  for (const Size& size : kSizes)
  {
    for (float angle : { 30.0f, 60.0f, 120.0f })
    {
      for (const auto& turn : turns)
      {
        shadelab::Scene s;
        s.camera.viewAngle = angle;
        s.camera.azimuth = turn[0];
        s.camera.elevation = turn[1];
        vtkNew<slScene> scene;
        scene->SetScene(s);
        vtkNew<vtkCamera> camera;
        scene->ApplyCamera(camera, bounds, size.width, size.height);
        const double aspect = static_cast<double>(size.width) / size.height;
        for (int corner = 0; corner < 8; ++corner)
        {
          const double p[3] = { bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + ((corner >> 2) & 1)] };
          const std::array<double, 3> ndc = project(camera, aspect, p);
          EXPECT_LE(std::abs(ndc[0]), 1.0) << size.width << "x" << size.height << " angle " << angle << " corner " << corner;
          EXPECT_LE(std::abs(ndc[1]), 1.0) << size.width << "x" << size.height << " angle " << angle << " corner " << corner;
          EXPECT_LE(std::abs(ndc[2]), 1.0) << "corner " << corner << " clipped";
        }
      }
    }
  }
}

TEST(CameraPlacement, TurnsLikeVTKsAzimuthAndElevation)
{
  // VTK's own camera operations, as vtkRenderer::ResetCamera leaves the
  // camera (looking down -z at the centre) before turning it.
  const double bounds[6] = { -1.0, 3.0, -2.0, 0.0, 0.5, 1.5 };
  const float ups[][3] = { { 0, 1, 0 }, { 0.3f, 1, 0.2f }, { 1, 0, 0 } };
  for (const auto& up : ups)
  {
    for (float azimuth : { 0.0f, 140.0f, -75.0f, 300.0f })
    {
      for (float elevation : { 0.0f, 12.0f, -40.0f, 80.0f })
      {
        shadelab::Scene s;
        s.camera.azimuth = azimuth;
        s.camera.elevation = elevation;
        s.camera.viewUp = glm::vec3(up[0], up[1], up[2]);
        vtkNew<slScene> scene;
        scene->SetScene(s);
        vtkNew<vtkCamera> placed;
        scene->ApplyCamera(placed, bounds, 320, 240);

        vtkNew<vtkCamera> vtk;
        vtk->SetViewUp(up[0], up[1], up[2]);
        vtk->SetFocalPoint(1.0, -1.0, 1.0);
        vtk->SetPosition(1.0, -1.0, 2.0);
        vtk->Azimuth(azimuth);
        vtk->Elevation(elevation);
        vtk->OrthogonalizeViewUp();
        double a[3], b[3];
        placed->GetDirectionOfProjection(a);
        vtk->GetDirectionOfProjection(b);
        const double* ua = placed->GetViewUp();
        const double* ub = vtk->GetViewUp();
        for (int i = 0; i < 3; ++i)
        {
          EXPECT_NEAR(a[i], b[i], 1e-9) << "azimuth " << azimuth << " elevation " << elevation;
          EXPECT_NEAR(ua[i], ub[i], 1e-9) << "azimuth " << azimuth << " elevation " << elevation;
        }
        const double* f = placed->GetFocalPoint();
        EXPECT_NEAR(f[0], 1.0, 1e-12);
        EXPECT_NEAR(f[1], -1.0, 1e-12);
        EXPECT_NEAR(f[2], 1.0, 1e-12);
      }
    }
  }
}

TEST(CameraPlacement, DistanceFillsTheNarrowerDirection)
{
  // Bounding sphere radius r, vertical view angle 30 degrees: landscape and
  // square images fit it vertically (d = r / sin 15 deg); a portrait image
  // fits it horizontally, where the half angle is atan(tan 15 deg * w/h).
  const double bounds[6] = { 0.0, 2.0, 0.0, 2.0, 0.0, 1.0 };
  const double r = 1.5, pi = 3.14159265358979323846;
  const double half = 15.0 * pi / 180.0;
  vtkNew<slScene> scene;
  for (const Size& size : kSizes)
  {
    vtkNew<vtkCamera> camera;
    scene->ApplyCamera(camera, bounds, size.width, size.height);
    const double aspect = std::min(1.0, static_cast<double>(size.width) / size.height);
    EXPECT_NEAR(camera->GetDistance(), r / std::sin(std::atan(std::tan(half) * aspect)), 1e-9)
      << size.width << "x" << size.height;
  }
}

TEST(CameraPlacement, GivenPositionIsKeptAndUpOrthogonalised)
{
  shadelab::Scene s;
  s.camera.hasPosition = true;
  s.camera.position = glm::vec3(1.0f, 2.0f, 3.0f);
  s.camera.focalPoint = glm::vec3(0.0f, 0.0f, 0.0f);
  s.camera.viewUp = glm::vec3(0.0f, 1.0f, 0.0f);
  vtkNew<slScene> scene;
  scene->SetScene(s);
  vtkNew<vtkCamera> camera;
  const double bounds[6] = { -1, 1, -1, 1, -1, 1 };
  scene->ApplyCamera(camera, bounds, 120, 400);
  const double* p = camera->GetPosition();
  EXPECT_DOUBLE_EQ(p[0], 1.0);
  EXPECT_DOUBLE_EQ(p[1], 2.0);
  EXPECT_DOUBLE_EQ(p[2], 3.0);
  double d[3];
  camera->GetDirectionOfProjection(d);
  const double* up = camera->GetViewUp();
  EXPECT_NEAR(d[0] * up[0] + d[1] * up[1] + d[2] * up[2], 0.0, 1e-12);
}
