// slNormalMapFilter, slBumpMapFilter, slDisplacementFilter on a unit plane
// whose UVs equal its x, y coordinates, with synthetic images whose expected
// normals are computed here by hand; the Bevy maps; and bad input.
#include "TestFolder.h"

#include "slBumpMapFilter.h"
#include "slDisplacementFilter.h"
#include "slImageWriter.h"
#include "slMeshReader.h"
#include "slNormalMapFilter.h"
#include "VTKErrors.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>

namespace
{
using Vec = std::array<double, 3>;

/// The unit square in z = 0 cut into n x n quads, UV = (x, y), normal +z.
vtkSmartPointer<vtkPolyData> plane(int n)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> uv;
  uv->SetName("UV");
  uv->SetNumberOfComponents(2);
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      points->InsertNextPoint(static_cast<double>(i) / n, static_cast<double>(j) / n, 0);
      uv->InsertNextTuple2(static_cast<double>(i) / n, static_cast<double>(j) / n);
    }
  }
  vtkNew<vtkCellArray> quads;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const vtkIdType a = j * (n + 1) + i;
      const vtkIdType q[] = { a, a + 1, a + n + 2, a + n + 1 };
      quads->InsertNextCell(4, q);
    }
  }
  auto m = vtkSmartPointer<vtkPolyData>::New();
  m->SetPoints(points);
  m->SetPolys(quads);
  m->GetPointData()->SetTCoords(uv);
  return m;
}

/// Writes a w x h RGB PNG whose texel (i, j) (row 0 at the bottom) is rgb(i, j).
std::string writePNG(const TestFolder& folder, const std::string& name, int w, int h,
  const std::function<std::array<unsigned char, 3>(int, int)>& rgb)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(w, h, 1);
  vtkNew<vtkUnsignedCharArray> s;
  s->SetNumberOfComponents(3);
  s->SetNumberOfTuples(w * h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const auto c = rgb(i, j);
      s->SetTypedTuple(j * w + i, c.data());
    }
  }
  image->GetPointData()->SetScalars(s);
  vtkNew<slImageWriter> writer;
  writer->SetInputData(image);
  const std::string path = folder.path(name);
  writer->SetFileName(path.c_str());
  EXPECT_EQ(callError(writer, [&] { return writer->Write(); }), "");
  return path;
}

struct Result
{
  vtkSmartPointer<vtkPolyData> out;
  std::string error;
};

Result update(vtkPolyDataAlgorithm* f, vtkPolyData* input)
{
  f->SetInputData(input);
  Result r;
  vtkNew<vtkCallbackCommand> keep;
  keep->SetClientData(&r.error);
  keep->SetCallback([](vtkObject*, unsigned long, void* text, void* message) {
    *static_cast<std::string*>(text) = static_cast<const char*>(message);
  });
  f->AddObserver(vtkCommand::ErrorEvent, keep);
  f->Update();
  r.out = f->GetOutput();
  return r;
}

Vec normalized(const Vec& v)
{
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return { v[0] / l, v[1] / l, v[2] / l };
}

Vec normalAt(vtkPolyData* m, vtkIdType i)
{
  Vec v;
  m->GetPointData()->GetNormals()->GetTuple(i, v.data());
  return v;
}

void expectNear(const Vec& a, const Vec& b, double tol, const std::string& where)
{
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_NEAR(a[k], b[k], tol) << where << " component " << k;
  }
}

double decode(int byte)
{
  return byte / 255.0 * 2.0 - 1.0;
}
} // namespace

TEST(Detail, NormalMapDecodesOpenGLAndDirectXWithStrength)
{
  const TestFolder folder;
  const std::string map = writePNG(folder, "n.png", 4, 4, [](int, int) { return std::array<unsigned char, 3>{ 204, 50, 230 }; });
  const double x = decode(204), y = decode(50), z = decode(230);
  struct Case
  {
    bool greenDown;
    double strength;
    Vec expected; // the plane's frame is T = +x, B = +y, N = +z
  };
  for (const Case& c : { Case{ false, 1, normalized({ x, y, z }) }, Case{ true, 1, normalized({ x, -y, z }) },
         Case{ false, 0, { 0, 0, 1 } }, Case{ false, 2, normalized({ 2 * x, 2 * y, z }) } })
  {
    vtkNew<slNormalMapFilter> f;
    f->SetFileName(map.c_str());
    f->SetGreenDown(c.greenDown);
    f->SetStrength(c.strength);
    Result r = update(f, plane(4));
    ASSERT_EQ(r.error, "");
    for (vtkIdType i = 0; i < r.out->GetNumberOfPoints(); ++i)
    {
      expectNear(normalAt(r.out, i), c.expected, 1e-5, "point " + std::to_string(i));
    }
  }
}

TEST(Detail, NormalMapIsSampledBilinearly)
{
  // Two texels, red 0 and 255, centred at u = 0.25 and 0.75: red is linear
  // in between, 255 (u - 0.25) / 0.5.
  const TestFolder folder;
  const std::string map =
    writePNG(folder, "ramp.png", 2, 1, [](int i, int) { return std::array<unsigned char, 3>{ static_cast<unsigned char>(i ? 255 : 0), 128, 255 }; });
  vtkNew<slNormalMapFilter> f;
  f->SetFileName(map.c_str());
  Result r = update(f, plane(8));
  ASSERT_EQ(r.error, "");
  for (vtkIdType i = 0; i < r.out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    r.out->GetPoint(i, p);
    if (p[0] < 0.25 || p[0] > 0.75)
    {
      continue;
    }
    const double red = 255 * (p[0] - 0.25) / 0.5;
    expectNear(normalAt(r.out, i), normalized({ red / 255 * 2 - 1, decode(128), 1 }), 1e-5, "u " + std::to_string(p[0]));
  }
}

namespace
{
/// A 256-texel ramp: texel i has grey i, so h(u) = (256 u - 0.5) / 255 and
/// dh/du = 256 / 255 away from the wrap-around at u = 0 and 1.
std::string writeRamp(const TestFolder& folder)
{
  return writePNG(folder, "h.png", 256, 4, [](int i, int) {
    const auto g = static_cast<unsigned char>(i);
    return std::array<unsigned char, 3>{ g, g, g };
  });
}
} // namespace

TEST(Detail, BumpMapNormalsFollowTheHeightGradient)
{
  const TestFolder folder;
  const std::string ramp = writeRamp(folder);
  const double slope = 256.0 / 255.0;
  for (bool invert : { false, true })
  {
    vtkNew<slBumpMapFilter> f;
    f->SetFileName(ramp.c_str());
    f->SetScale(0.1);
    f->SetInvertHeight(invert);
    Result r = update(f, plane(16));
    ASSERT_EQ(r.error, "");
    const double g = (invert ? -1 : 1) * 0.1 * slope;
    for (vtkIdType i = 0; i < r.out->GetNumberOfPoints(); ++i)
    {
      double p[3];
      r.out->GetPoint(i, p);
      if (p[0] > 0.05 && p[0] < 0.95)
      {
        expectNear(normalAt(r.out, i), normalized({ -g, 0, 1 }), 1e-5, "u " + std::to_string(p[0]));
      }
    }
  }
}

TEST(Detail, DisplacementMovesPointsAndRecomputesNormals)
{
  const TestFolder folder;
  const std::string ramp = writeRamp(folder);
  vtkNew<slDisplacementFilter> f;
  f->SetFileName(ramp.c_str());
  f->SetScale(0.2);
  Result r = update(f, plane(16));
  ASSERT_EQ(r.error, "");
  const double slope = 0.2 * 256.0 / 255.0;
  for (vtkIdType i = 0; i < r.out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    r.out->GetPoint(i, p);
    if (p[0] > 0.05 && p[0] < 0.95)
    {
      EXPECT_NEAR(p[2], 0.2 * (256 * p[0] - 0.5) / 255, 1e-6) << "point " << i;
    }
    if (p[0] > 0.2 && p[0] < 0.8)
    {
      expectNear(normalAt(r.out, i), normalized({ -slope, 0, 1 }), 1e-5, "point " + std::to_string(i));
    }
  }
}

TEST(Detail, DisplacementBeyondTheFloatRangeIsAnError)
{
  // Points moved past float's range cannot get normals: a one-line error
  // (it was an empty mesh with no reason).
  const TestFolder folder;
  // A 2 x 2 float height map (PFM: header, then little-endian RGB floats) of 3e38.
  std::string pfm = "PF\n2 2\n-1.0\n";
  const float height = 3e38f;
  for (int k = 0; k < 12; ++k)
  {
    pfm.append(reinterpret_cast<const char*>(&height), sizeof height);
  }
  folder.write("huge.pfm", pfm);
  const std::string path = folder.path("huge.pfm");
  vtkNew<slDisplacementFilter> f;
  f->SetFileName(path.c_str());
  f->SetScale(10.0);
  Result r = update(f, plane(4));
  EXPECT_NE(r.error.find("displaced mesh: point "), std::string::npos) << r.error;
  EXPECT_EQ(r.out->GetNumberOfPoints(), 0);
}

TEST(Detail, BevyNormalMapAgreesWithItsInvertedDepthMap)
{
  // The bevy normal map was authored from the depth map: bump normals from
  // height = 1 - depth must lean the same way as the map's (green up), and
  // the opposite way if the depth were used as height.
  const std::string textures = SHADELAB_DATA_DIR "/textures/";
  vtkNew<slNormalMapFilter> nm;
  nm->SetFileName((textures + "bevy_parallax_cube_normal.png").c_str());
  Result mapped = update(nm, plane(96));
  ASSERT_EQ(mapped.error, "");
  auto correlation = [&](bool invert) {
    vtkNew<slBumpMapFilter> bump;
    bump->SetFileName((textures + "bevy_parallax_cube_depth.png").c_str());
    bump->SetInvertHeight(invert);
    Result b = update(bump, plane(96));
    EXPECT_EQ(b.error, "");
    double sab = 0, saa = 0, sbb = 0;
    for (vtkIdType i = 0; i < b.out->GetNumberOfPoints(); ++i)
    {
      const Vec a = normalAt(mapped.out, i), c = normalAt(b.out, i);
      for (int k = 0; k < 2; ++k)
      {
        sab += a[k] * c[k];
        saa += a[k] * a[k];
        sbb += c[k] * c[k];
      }
    }
    return sab / std::sqrt(saa * sbb);
  };
  EXPECT_GT(correlation(true), 0.5);
  EXPECT_LT(correlation(false), -0.5);
}

TEST(Detail, SpotTakesTheNormalMapThroughItsUVs)
{
  vtkNew<slMeshReader> reader;
  reader->SetFileName(SHADELAB_DATA_DIR "/meshes/spot.obj");
  reader->Update();
  vtkNew<slNormalMapFilter> f;
  f->SetFileName(SHADELAB_DATA_DIR "/textures/bevy_parallax_cube_normal.png");
  Result r = update(f, reader->GetOutput());
  ASSERT_EQ(r.error, "");
  ASSERT_GE(r.out->GetNumberOfPoints(), reader->GetOutput()->GetNumberOfPoints());
  int changed = 0;
  for (vtkIdType i = 0; i < r.out->GetNumberOfPoints(); ++i)
  {
    const Vec n = normalAt(r.out, i);
    EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-5);
    changed += std::fabs(n[2]) < 0.999; // not everything points along z
  }
  EXPECT_GT(changed, 0);
}

TEST(Detail, BadImagesAndMissingUVsGiveClearErrors)
{
  const TestFolder folder;
  folder.write("not-an-image.png", "hello");
  const std::string missing = folder.path("missing.png");
  const std::string wrong = folder.path("not-an-image.png");
  for (const std::string& file : { missing, wrong })
  {
    vtkNew<slNormalMapFilter> nm;
    nm->SetFileName(file.c_str());
    Result r = update(nm, plane(2));
    EXPECT_NE(r.error.find(file), std::string::npos) << r.error;
    EXPECT_EQ(r.out->GetNumberOfPoints(), 0);
    vtkNew<slDisplacementFilter> d;
    d->SetFileName(file.c_str());
    Result rd = update(d, plane(2));
    EXPECT_NE(rd.error.find(file), std::string::npos) << rd.error;
    EXPECT_EQ(rd.out->GetNumberOfPoints(), 0);
  }
  vtkSmartPointer<vtkPolyData> noUV = plane(2);
  noUV->GetPointData()->SetTCoords(nullptr);
  vtkNew<slBumpMapFilter> bump;
  bump->SetFileName(SHADELAB_DATA_DIR "/textures/bevy_parallax_cube_depth.png");
  Result r = update(bump, noUV);
  EXPECT_NE(r.error.find("no texture coordinates"), std::string::npos) << r.error;
  EXPECT_EQ(r.out->GetNumberOfPoints(), 0);
}
