// slPolyDataNormals against analytic normals on irregular spheres, ellipsoids
// and tori (docs/normals.md's accuracy table is this test's output), and
// against VTK's own filters for the weightings they implement.
#include "NormalsTestMeshes.h"

#include "slPolyDataNormals.h"

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyDataNormals.h>
#include <vtkTriangleMeshPointNormals.h>

#include <gtest/gtest.h>

#include <cstdio>

namespace
{
struct Error
{
  double mean = 0, max = 0;
};

vtkSmartPointer<vtkPolyData> normalsOf(vtkPolyData* mesh, int weighting)
{
  vtkNew<slPolyDataNormals> f;
  f->SetInputData(mesh);
  f->SetWeighting(weighting);
  f->SplittingOff();
  f->ConsistencyOff();
  f->Update();
  vtkSmartPointer<vtkPolyData> out = f->GetOutput();
  return out;
}

Error errorAgainst(vtkPolyData* out, const char* reference)
{
  vtkDataArray* n = out->GetPointData()->GetArray("Normals");
  vtkDataArray* a = out->GetPointData()->GetArray(reference);
  Error e;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    n->GetTuple(i, p);
    a->GetTuple(i, q);
    const double d = normalstest::angleDegrees(p, q);
    e.mean += d;
    e.max = std::max(e.max, d);
  }
  e.mean /= static_cast<double>(out->GetNumberOfPoints());
  return e;
}

struct Shape
{
  const char* name;
  vtkSmartPointer<vtkPolyData> mesh;
};

std::vector<Shape> shapes()
{
  return {
    { "irregular sphere r=1", normalstest::irregularEllipsoid({ 1, 1, 1 }, 7) },
    { "irregular ellipsoid 1.5 x 1 x 0.6", normalstest::irregularEllipsoid({ 1.5, 1, 0.6 }, 11) },
    { "coarse irregular ellipsoid 1.5 x 1 x 0.6", normalstest::irregularEllipsoid({ 1.5, 1, 0.6 }, 13, 2) },
    { "irregular torus R=1 a=0.35", normalstest::irregularTorus(1.0, 0.35, 64, 24, 5) },
    { "coarse irregular torus R=1 a=0.35", normalstest::irregularTorus(1.0, 0.35, 24, 10, 3) },
  };
}
} // namespace

TEST(NormalsAccuracy, TableOfAngularErrors)
{
  std::printf("| surface | triangles | uniform mean / max (°) | area mean / max (°) | angle mean / max (°) | "
              "max mean / max (°) | best mean |\n|---|---|---|---|---|---|---|\n");
  for (const Shape& s : shapes())
  {
    Error e[4];
    for (int w = 0; w < 4; ++w)
    {
      e[w] = errorAgainst(normalsOf(s.mesh, w), "AnalyticNormals");
    }
    int best = 0;
    for (int w = 1; w < 4; ++w)
    {
      best = e[w].mean < e[best].mean ? w : best;
    }
    std::printf("| %s | %lld |", s.name, static_cast<long long>(s.mesh->GetNumberOfPolys()));
    for (int w = 0; w < 4; ++w)
    {
      std::printf(" %.3g / %.3g |", e[w].mean, e[w].max);
    }
    std::printf(" %s |\n", slPolyDataNormals::GetWeightingName(best));

    // On irregular triangulations angle weighting beats uniform weighting.
    EXPECT_LT(e[slPolyDataNormals::ANGLE].mean, e[slPolyDataNormals::UNIFORM].mean) << s.name;
    for (int w = 0; w < 4; ++w)
    {
      EXPECT_LT(e[w].max, 30.0) << s.name << " " << w; // sanity: no flipped or NaN normal
    }
  }
}

TEST(NormalsAccuracy, MaxWeightsAreExactOnASphere)
{
  for (unsigned seed : { 1u, 2u, 3u })
  {
    const Error e = errorAgainst(
      normalsOf(normalstest::irregularEllipsoid({ 2, 2, 2 }, seed), slPolyDataNormals::MAX), "AnalyticNormals");
    EXPECT_LT(e.max, 1e-4) << "seed " << seed;
  }
  // The same weights are not exact on an ellipsoid: the test can tell.
  const Error ellipsoid = errorAgainst(
    normalsOf(normalstest::irregularEllipsoid({ 1.5, 1, 0.6 }, 1), slPolyDataNormals::MAX), "AnalyticNormals");
  EXPECT_GT(ellipsoid.max, 1e-3);
}

TEST(NormalsAccuracy, UniformWeightingMatchesVTKPolyDataNormals)
{
  vtkSmartPointer<vtkPolyData> mesh = normalstest::irregularTorus(1.0, 0.35, 40, 16, 9);
  vtkNew<vtkPolyDataNormals> vtk;
  vtk->SetInputData(mesh);
  vtk->SplittingOff();
  vtk->ConsistencyOff();
  vtk->Update();
  vtkPolyData* ref = vtk->GetOutput();
  ref->GetPointData()->GetNormals()->SetName("VTKNormals");
  vtkSmartPointer<vtkPolyData> ours = normalsOf(mesh, slPolyDataNormals::UNIFORM);
  ours->GetPointData()->AddArray(ref->GetPointData()->GetArray("VTKNormals"));
  EXPECT_LT(errorAgainst(ours, "VTKNormals").max, 1e-3);
}

TEST(NormalsAccuracy, AreaWeightingMatchesVTKTriangleMeshPointNormals)
{
  vtkSmartPointer<vtkPolyData> mesh = normalstest::irregularEllipsoid({ 1.5, 1, 0.6 }, 4, 3);
  vtkNew<vtkTriangleMeshPointNormals> vtk;
  vtk->SetInputData(mesh);
  vtk->Update();
  vtkPolyData* ref = vtk->GetOutput();
  ref->GetPointData()->GetNormals()->SetName("VTKNormals");
  vtkSmartPointer<vtkPolyData> ours = normalsOf(mesh, slPolyDataNormals::AREA);
  ours->GetPointData()->AddArray(ref->GetPointData()->GetArray("VTKNormals"));
  EXPECT_LT(errorAgainst(ours, "VTKNormals").max, 1e-3);
}

TEST(NormalsAccuracy, FloatMeshesOfAnySizeGetTheSameNormals)
{
  // Float normals from float points: an edge cross product squared is about
  // the 4th power of the mesh's size, which overflows float for sizes above
  // about 1e9 and underflows below about 1e-9. A mesh of astronomical or
  // molecular size, far from the origin too, must get the normals of the
  // same mesh at size 1 (checked for every weighting and every point).
  vtkSmartPointer<vtkPolyData> unit = normalstest::irregularEllipsoid({ 1.0, 0.7, 0.5 }, 5, 3);
  for (int weighting = slPolyDataNormals::UNIFORM; weighting <= slPolyDataNormals::MAX; ++weighting)
  {
    vtkSmartPointer<vtkPolyData> reference = normalsOf(unit, weighting);
    for (double size : { 1e-30, 1e-22, 1e-12, 1e12, 1e20, 1e30 })
    {
      vtkNew<vtkPoints> points;
      points->SetDataTypeToFloat();
      for (vtkIdType i = 0; i < unit->GetNumberOfPoints(); ++i)
      {
        double p[3];
        unit->GetPoint(i, p);
        points->InsertNextPoint(size * (p[0] + 3.0), size * p[1], size * p[2]);
      }
      vtkNew<vtkPolyData> mesh;
      mesh->SetPoints(points);
      mesh->SetPolys(unit->GetPolys());
      vtkSmartPointer<vtkPolyData> out = normalsOf(mesh, weighting);
      ASSERT_EQ(out->GetNumberOfPoints(), reference->GetNumberOfPoints()) << size;
      double worst = 0.0;
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      {
        double a[3], b[3];
        out->GetPointData()->GetArray("Normals")->GetTuple(i, a);
        reference->GetPointData()->GetArray("Normals")->GetTuple(i, b);
        // A unit normal (not NaN, not the zero vector), close to the reference.
        ASSERT_NEAR(std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]), 1.0, 1e-5) << size << ", point " << i;
        const double angle = normalstest::angleDegrees(a, b);
        ASSERT_TRUE(angle <= 180.0) << size << ", point " << i; // not NaN
        worst = std::max(worst, angle);
      }
      // Float rounding of the scaled coordinates moves the normals by far
      // less than this.
      EXPECT_LT(worst, 1e-3) << "size " << size << ", weighting " << slPolyDataNormals::GetWeightingName(weighting);
      double p[3];
      out->GetPoint(0, p); // the output keeps the input's coordinates
      EXPECT_EQ(static_cast<float>(p[1]), static_cast<float>(size * unit->GetPoint(0)[1]));
    }
  }
}
