// shadelab_bench_normals [--help] [--runs N] [--threads N] [--triangles N]
// Medians of slPolyDataNormals and its peers on one generated mesh, side by
// side in one run, with their ranges, ratios and peak memory above the input.
#include "BenchArguments.h"
#include "BenchMachine.h"
#include "BenchMemory.h"
#include "BenchOpenMesh.h"
#include "BenchTiming.h"
#include "BenchTorus.h"

#include "slPolyDataNormals.h"

#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkSMPTools.h>
#include <vtkTriangleMeshPointNormals.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace
{
struct Row
{
  std::string name;
  BenchTimes times;
};
} // namespace

int main(int argc, char** argv)
{
  BenchArguments args("shadelab_bench_normals",
    "slPolyDataNormals against vtkTriangleMeshPointNormals, vtkPolyDataNormals and OpenMesh on one torus", 7);
  long long triangles = 2000000;
  args.integer("triangles", "about N triangles in the generated torus (default 2000000)", &triangles, 100,
    1000000000);
  if (!args.parse(argc, argv))
  {
    return args.exitCode();
  }
  const int runs = args.runs();
  BenchMachine::measure().print();
  vtkSmartPointer<vtkPolyData> mesh = slBenchTorus(triangles);
  const double tris = static_cast<double>(mesh->GetNumberOfPolys());
  std::printf("mesh: %lld points, %lld triangles, %.1f MiB; medians (and ranges) of %d runs\n\n",
    static_cast<long long>(mesh->GetNumberOfPoints()), static_cast<long long>(mesh->GetNumberOfPolys()),
    mesh->GetActualMemorySize() / 1024.0, runs);

  auto ours = [&](int weighting, bool split) {
    vtkNew<slPolyDataNormals> f;
    f->SetInputData(mesh);
    f->SetWeighting(weighting);
    f->SetSplitting(split);
    f->SetConsistency(split);
    return [f = vtkSmartPointer<slPolyDataNormals>(f.GetPointer())]() {
      f->Modified();
      f->Update();
    };
  };
  vtkNew<vtkTriangleMeshPointNormals> tmpn;
  tmpn->SetInputData(mesh);
  vtkNew<vtkPolyDataNormals> pdnPlain, pdnDefault;
  pdnPlain->SetInputData(mesh);
  pdnPlain->SplittingOff();
  pdnPlain->ConsistencyOff();
  pdnDefault->SetInputData(mesh);
  slBenchOpenMesh om(mesh);

  // 1. Vertex normals without splitting.
  std::vector<Row> plain;
  for (int w = 0; w < 4; ++w)
  {
    plain.push_back({ std::string("slPolyDataNormals ") + slPolyDataNormals::GetWeightingName(w),
      timeRuns(runs, ours(w, false)) });
  }
  const Row tmpnRow{ "vtkTriangleMeshPointNormals", timeRuns(runs, [&] {
                      tmpn->Modified();
                      tmpn->Update();
                    }) };
  const Row pdnRow{ "vtkPolyDataNormals (split/cons off)", timeRuns(std::min(runs, 3), [&] {
                     pdnPlain->Modified();
                     pdnPlain->Update();
                   }) };
  const Row omRow{ "OpenMesh update_face+vertex_normals", timeRuns(runs, [&] { om.UpdateNormals(); }) };
  const double tTMPN = tmpnRow.times.median(), tPDN = pdnRow.times.median(), tOM = omRow.times.median();
  std::printf("vertex normals, no splitting, no consistency\n");
  std::printf("%-36s %9s %15s %8s %10s %12s %12s %11s\n", "", "median ms", "range ms", "cpu ms", "M tris/s",
    "x TriMeshPN", "x PolyDataN", "x OpenMesh");
  auto print = [&](const Row& r) {
    const double s = r.times.median();
    char range[32];
    std::snprintf(range, sizeof(range), "%.1f-%.1f", r.times.minimum() * 1e3, r.times.maximum() * 1e3);
    std::printf("%-36s %9.1f %15s %8.1f %10.1f %12.2f %12.2f %11.2f\n", r.name.c_str(), s * 1e3, range,
      r.times.medianCpu() * 1e3, tris / s / 1e6, tTMPN / s, tPDN / s, tOM / s);
  };
  for (const Row& r : plain)
  {
    print(r);
  }
  print(tmpnRow);
  print(pdnRow);
  print(omRow);

  // 2. Feature-angle splitting and consistency on.
  const BenchTimes split = timeRuns(runs, ours(slPolyDataNormals::ANGLE, true));
  const BenchTimes pdnSplit = timeRuns(std::min(runs, 3), [&] {
    pdnDefault->Modified();
    pdnDefault->Update();
  });
  std::printf("\nsplitting (30 degrees) and consistency on\n");
  std::printf("%-36s %9s %15s %8s %10s %12s   output points\n", "", "median ms", "range ms", "cpu ms", "M tris/s",
    "x PolyDataN");
  vtkNew<slPolyDataNormals> check;
  check->SetInputData(mesh);
  check->Update();
  auto printSplit = [&](const char* name, const BenchTimes& t, vtkIdType points) {
    char range[32];
    std::snprintf(range, sizeof(range), "%.1f-%.1f", t.minimum() * 1e3, t.maximum() * 1e3);
    std::printf("%-36s %9.1f %15s %8.1f %10.1f %12.2f   %lld\n", name, t.median() * 1e3, range, t.medianCpu() * 1e3,
      tris / t.median() / 1e6, pdnSplit.median() / t.median(), static_cast<long long>(points));
  };
  printSplit("slPolyDataNormals angle (defaults)", split, check->GetOutput()->GetNumberOfPoints());
  printSplit("vtkPolyDataNormals (defaults)", pdnSplit, pdnDefault->GetOutput()->GetNumberOfPoints());

  // 3. Peak memory above the input, each in a fresh child process.
  const double input = mesh->GetActualMemorySize() * 1024.0;
  std::printf("\npeak resident memory above the input (input mesh: %.1f MiB)\n", input / 1048576.0);
  auto memory = [&](const char* name, const std::function<void()>& job) {
    const long long peak = slPeakMemoryAbove(job);
    std::printf("%-36s %9.1f MiB  %5.2f x input\n", name, peak / 1048576.0, peak / input);
  };
  memory("slPolyDataNormals angle, no split", ours(slPolyDataNormals::ANGLE, false));
  memory("slPolyDataNormals angle, split+cons", ours(slPolyDataNormals::ANGLE, true));
  memory("vtkTriangleMeshPointNormals", [&] {
    tmpn->Modified();
    tmpn->Update();
  });
  memory("vtkPolyDataNormals (defaults)", [&] {
    pdnDefault->Modified();
    pdnDefault->Update();
  });
  return 0;
}
