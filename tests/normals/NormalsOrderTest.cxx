// Vertex normals do not depend on the order of the points and polygons, nor
// on how the work is cut into chunks: a mesh whose points and triangles are
// shuffled (and each triangle's corners rotated) gets the ordered mesh's
// normals, permuted, for every weighting, thread count and point type.
#include "NormalsTestMeshes.h"
#include "ShuffledMesh.h"

#include "slPolyDataNormals.h"
#include "shadelab/slVertexNormalsCore.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

namespace
{
using normalstest::Mesh;
using normalstest::meshOf;
using normalstest::polyDataOf;
using normalstest::randomNumbering;
using normalstest::shuffled;

/// A serial stand-in for a thread pool of @p threads threads that runs the
/// sub-ranges last first, so that nothing may rely on the order chunks run in.
slnormals::Parallel backwards(int threads)
{
  slnormals::Parallel p;
  p.threads = threads;
  p.forRange = [](int64_t begin, int64_t end, int64_t grain, const slnormals::Parallel::Body& body) {
    const int64_t step = std::max<int64_t>(grain, 1);
    for (int64_t b = begin + (end - begin - 1) / step * step; b >= begin; b -= step)
    {
      body(b, std::min(end, b + step));
    }
  };
  return p;
}

/// The normals of @p poly's points, computed in mesh order and shuffled on
/// each of @p threadCounts, against those of one thread in mesh order: no
/// component more than @p tolerance apart (float rounding of sums taken in
/// another order: a few units in the last place).
template <typename T>
void expectSameNormalsInAnyOrder(vtkPolyData* poly, std::vector<int> threadCounts = { 1, 2, 3, 8 },
  bool rotateCorners = true, double tolerance = 2e-6)
{
  Mesh<T> ordered = meshOf<T>(poly);
  ASSERT_GT(ordered.offsets.size(), 65537u) << "too small for the chunked path";
  std::mt19937 rng(7);
  const std::vector<int64_t> newId = randomNumbering(ordered.numPoints(), rng);
  Mesh<T> mixed = shuffled(ordered, newId, rng, rotateCorners);
  const int64_t n = ordered.numPoints();
  for (int w = 0; w < 4; ++w)
  {
    const auto weighting = static_cast<slnormals::Weighting>(w);
    std::vector<float> reference(static_cast<size_t>(3 * n));
    ASSERT_TRUE(
      slnormals::computeVertexNormals(ordered.view(), ordered.xyz.data(), n, weighting, reference.data(), backwards(1)));
    for (int threads : threadCounts)
    {
      std::vector<float> a(static_cast<size_t>(3 * n), -9.f), b(static_cast<size_t>(3 * n), -9.f);
      ASSERT_TRUE(
        slnormals::computeVertexNormals(ordered.view(), ordered.xyz.data(), n, weighting, a.data(), backwards(threads)));
      ASSERT_TRUE(
        slnormals::computeVertexNormals(mixed.view(), mixed.xyz.data(), n, weighting, b.data(), backwards(threads)));
      double worstOrdered = 0, worstShuffled = 0;
      for (int64_t v = 0; v < n; ++v)
      {
        const int64_t s = newId[static_cast<size_t>(v)];
        for (int c = 0; c < 3; ++c)
        {
          const float r = reference[static_cast<size_t>(3 * v + c)];
          worstOrdered = std::max(worstOrdered, std::fabs(double(a[static_cast<size_t>(3 * v + c)]) - r));
          worstShuffled = std::max(worstShuffled, std::fabs(double(b[static_cast<size_t>(3 * s + c)]) - r));
        }
      }
      EXPECT_LT(worstOrdered, tolerance) << "weighting " << w << ", " << threads << " threads";
      EXPECT_LT(worstShuffled, tolerance) << "weighting " << w << ", " << threads << " threads, shuffled";
    }
  }
}
} // namespace

TEST(NormalsOrder, ShuffledTorusGetsTheOrderedNormalsFloat)
{
  // 300 x 150 grid: 90 000 triangles, above the size where the work is chunked.
  expectSameNormalsInAnyOrder<float>(normalstest::irregularTorus(1.0, 0.35, 300, 150, 3));
}

TEST(NormalsOrder, ShuffledEllipsoidGetsTheOrderedNormalsDouble)
{
  // 81 920 triangles; double points take the scratch accumulator.
  expectSameNormalsInAnyOrder<double>(normalstest::irregularEllipsoid({ 1.5, 1.0, 0.6 }, 5, 6));
}

TEST(NormalsOrder, LargeShuffledTorusAskedAheadGetsTheOrderedNormals)
{
  // 640 x 420 grid: enough points that the shuffled mesh's scatter asks
  // for each block's points and sums ahead. Corners are not rotated: among
  // this many jittered triangles, the thinnest ones' float edges round
  // differently from another corner (up to 1.8e-5 with angle weights),
  // which would hide the sum order this test is about; and the largest
  // rounding difference over six times the points of the torus above is a
  // little larger (2.1e-6).
  vtkSmartPointer<vtkPolyData> torus = normalstest::irregularTorus(1.0, 0.35, 640, 420, 5);
  ASSERT_GE(torus->GetNumberOfPoints(), slnormals::detail::kLookaheadEntries);
  expectSameNormalsInAnyOrder<float>(torus, { 1, 2 }, false, 4e-6);
}

TEST(NormalsOrder, FilterGivesShuffledMeshesThePermutedNormals)
{
  vtkSmartPointer<vtkPolyData> poly = normalstest::irregularTorus(1.0, 0.35, 300, 150, 11);
  Mesh<float> ordered = meshOf<float>(poly);
  std::mt19937 rng(13);
  const std::vector<int64_t> newId = randomNumbering(ordered.numPoints(), rng);
  const Mesh<float> mixed = shuffled(ordered, newId, rng);
  auto normalsOf = [](vtkPolyData* in) {
    vtkNew<slPolyDataNormals> f;
    f->SetInputData(in);
    f->SplittingOff();
    f->Update();
    return vtkSmartPointer<vtkDataArray>(f->GetOutput()->GetPointData()->GetNormals());
  };
  vtkSmartPointer<vtkDataArray> a = normalsOf(polyDataOf(ordered)), b = normalsOf(polyDataOf(mixed));
  ASSERT_TRUE(a && b);
  double worst = 0;
  for (int64_t v = 0; v < ordered.numPoints(); ++v)
  {
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::fabs(a->GetComponent(v, c) - b->GetComponent(newId[static_cast<size_t>(v)], c)));
    }
  }
  EXPECT_LT(worst, 2e-6);
}
