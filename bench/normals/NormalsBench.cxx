// shadelab_bench_normals [--triangles N] [--runs R]
// Medians of slPolyDataNormals and its peers on one generated mesh, side by
// side in one run, with ratios and peak memory above the input.
#include "BenchMemory.h"
#include "BenchOpenMesh.h"
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
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace
{
/// CPU seconds of the last medianSeconds() run with the median wall time
/// (all threads together: steadier than wall time on a loaded machine).
double lastCPUSeconds = 0;

/// Median wall-clock seconds of @p runs runs of @p job.
double medianSeconds(int runs, const std::function<void()>& job)
{
  std::vector<std::pair<double, double>> t;
  for (int r = 0; r < runs; ++r)
  {
    const std::clock_t cpu = std::clock();
    const auto start = std::chrono::steady_clock::now();
    job();
    t.emplace_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
      static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC);
  }
  std::sort(t.begin(), t.end());
  lastCPUSeconds = t[t.size() / 2].second;
  return t[t.size() / 2].first;
}

struct Row
{
  std::string name;
  double seconds, cpu;
};
} // namespace

int main(int argc, char** argv)
{
  long long triangles = 2000000;
  int runs = 7;
  for (int i = 1; i + 1 < argc; i += 2)
  {
    if (!std::strcmp(argv[i], "--triangles"))
    {
      triangles = std::atoll(argv[i + 1]);
    }
    else if (!std::strcmp(argv[i], "--runs"))
    {
      runs = std::max(1, std::atoi(argv[i + 1]));
    }
  }
  vtkSmartPointer<vtkPolyData> mesh = slBenchTorus(triangles);
  const double tris = static_cast<double>(mesh->GetNumberOfPolys());
  std::printf("mesh: %lld points, %lld triangles, %.1f MiB; %d threads (%s); medians of %d runs\n\n",
    static_cast<long long>(mesh->GetNumberOfPoints()), static_cast<long long>(mesh->GetNumberOfPolys()),
    mesh->GetActualMemorySize() / 1024.0, vtkSMPTools::GetEstimatedNumberOfThreads(), vtkSMPTools::GetBackend(),
    runs);

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
    const double t = medianSeconds(runs, ours(w, false));
    plain.push_back({ std::string("slPolyDataNormals ") + slPolyDataNormals::GetWeightingName(w), t, lastCPUSeconds });
  }
  const double tTMPN = medianSeconds(runs, [&] {
    tmpn->Modified();
    tmpn->Update();
  });
  const double cTMPN = lastCPUSeconds;
  const double tPDN = medianSeconds(std::min(runs, 3), [&] {
    pdnPlain->Modified();
    pdnPlain->Update();
  });
  const double cPDN = lastCPUSeconds;
  const double tOM = medianSeconds(runs, [&] { om.UpdateNormals(); });
  const double cOM = lastCPUSeconds;
  std::printf("vertex normals, no splitting, no consistency\n");
  std::printf("%-36s %9s %8s %10s %12s %12s %11s\n", "", "median ms", "cpu ms", "M tris/s", "x TriMeshPN",
    "x PolyDataN", "x OpenMesh");
  auto print = [&](const std::string& name, double s, double cpu, double a, double b, double c) {
    std::printf("%-36s %9.1f %8.1f %10.1f %12.2f %12.2f %11.2f\n", name.c_str(), s * 1e3, cpu * 1e3, tris / s / 1e6,
      a / s, b / s, c / s);
  };
  for (const Row& r : plain)
  {
    print(r.name, r.seconds, r.cpu, tTMPN, tPDN, tOM);
  }
  print("vtkTriangleMeshPointNormals", tTMPN, cTMPN, tTMPN, tPDN, tOM);
  print("vtkPolyDataNormals (split/cons off)", tPDN, cPDN, tTMPN, tPDN, tOM);
  print("OpenMesh update_face+vertex_normals", tOM, cOM, tTMPN, tPDN, tOM);

  // 2. Feature-angle splitting and consistency on.
  const double tOursSplit = medianSeconds(runs, ours(slPolyDataNormals::ANGLE, true));
  const double cOursSplit = lastCPUSeconds;
  const double tPDNDefault = medianSeconds(std::min(runs, 3), [&] {
    pdnDefault->Modified();
    pdnDefault->Update();
  });
  const double cPDNDefault = lastCPUSeconds;
  std::printf("\nsplitting (30 degrees) and consistency on\n");
  std::printf("%-36s %9s %8s %10s %12s   output points\n", "", "median ms", "cpu ms", "M tris/s", "x PolyDataN");
  vtkNew<slPolyDataNormals> check;
  check->SetInputData(mesh);
  check->Update();
  std::printf("%-36s %9.1f %8.1f %10.1f %12.2f   %lld\n", "slPolyDataNormals angle (defaults)", tOursSplit * 1e3,
    cOursSplit * 1e3, tris / tOursSplit / 1e6, tPDNDefault / tOursSplit,
    static_cast<long long>(check->GetOutput()->GetNumberOfPoints()));
  std::printf("%-36s %9.1f %8.1f %10.1f %12.2f   %lld\n", "vtkPolyDataNormals (defaults)", tPDNDefault * 1e3,
    cPDNDefault * 1e3, tris / tPDNDefault / 1e6, 1.0,
    static_cast<long long>(pdnDefault->GetOutput()->GetNumberOfPoints()));

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
