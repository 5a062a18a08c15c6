// shadelab_bench_normals [--help] [--runs N] [--threads N] [--sizes LIST] [--order ordered|shuffled|both]
// slPolyDataNormals and its peers side by side in one run, on generated tori
// of several sizes, each in mesh order and shuffled: medians and ranges,
// ns per triangle, ratios taken round by round, the memory-bandwidth floor,
// the speed-up from one thread to all, and peak memory above the input.
#include "BenchArguments.h"
#include "BenchBareLoop.h"
#include "BenchMachine.h"
#include "BenchMemory.h"
#include "BenchOpenMesh.h"
#include "BenchTiming.h"
#include "BenchTorus.h"

#include "slPolyDataNormals.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkSMPTools.h>
#include <vtkTriangleMeshPointNormals.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace
{
/// Median, smallest and largest of per-round values, and how many reach a goal.
struct Spread
{
  double median = 0, low = 0, high = 0;
  int reaching = 0, of = 0;
};

/// a[r] / b[r] for every round r, summarised; @p goal counts the rounds at or above it.
Spread ratios(const BenchTimes& a, const BenchTimes& b, double goal)
{
  std::vector<double> r;
  for (size_t i = 0; i < a.wall.size() && i < b.wall.size(); ++i)
  {
    r.push_back(a.wall[i] / b.wall[i]);
  }
  Spread s;
  if (r.empty())
  {
    return s;
  }
  s.median = medianOf(r);
  s.low = *std::min_element(r.begin(), r.end());
  s.high = *std::max_element(r.begin(), r.end());
  s.of = static_cast<int>(r.size());
  s.reaching = static_cast<int>(std::count_if(r.begin(), r.end(), [&](double x) { return x >= goal; }));
  return s;
}

std::string format(const Spread& s)
{
  char text[64];
  std::snprintf(text, sizeof(text), "%.2f (%.2f-%.2f)", s.median, s.low, s.high);
  return text;
}

/// One mesh's results, kept for the summary at the end.
struct Result
{
  std::string label;
  double triangles = 0;
  double nsPerTriangle = 0;     ///< slPolyDataNormals angle, no split, all threads
  double bareNsPerTriangle = 0; ///< the bare loop, all threads (memory traffic alone)
  Spread overTMPN, overPDN, splitOverPDN, speedUp;
  Spread overBare;    ///< slPolyDataNormals' time over the bare loop's, all threads
  Spread bareSpeedUp; ///< the bare loop from one thread to all
  Spread pdnOverBare; ///< vtkPolyDataNormals (split/cons off) over the bare loop: the most its goal can be
  double floorRatio = 0, splitFloorRatio = 0;
};

/// Runs @p job with vtkSMPTools limited to one thread, then gives it
/// @p threads again. (VTK 9.1's vtkSMPTools::LocalScope leaves
/// GetEstimatedNumberOfThreads() at the scope's value afterwards, and filters
/// that size their work by it would then run on one thread.)
std::function<void()> onOneThread(int threads, std::function<void()> job)
{
  return [threads, job]() {
    vtkSMPTools::Initialize(1);
    job();
    vtkSMPTools::Initialize(threads);
  };
}

/// Parses "0.1,0.5,2,8" (millions of triangles).
std::string parseSizes(const std::string& text, std::vector<double>& sizes)
{
  sizes.clear();
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
  {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || *end || !(v >= 0.0001 && v <= 500))
    {
      return "'" + item + "' is not a number of millions of triangles from 0.0001 to 500";
    }
    sizes.push_back(v);
  }
  return sizes.empty() ? "no size given" : "";
}

/// A new slPolyDataNormals on @p mesh with @p weighting, splitting and
/// consistency as @p split says, updated by each call of the job.
std::function<void()> ours(vtkPolyData* mesh, int weighting, bool split)
{
  vtkSmartPointer<slPolyDataNormals> f = vtkSmartPointer<slPolyDataNormals>::New();
  f->SetInputData(mesh);
  f->SetWeighting(weighting);
  f->SetSplitting(split);
  f->SetConsistency(split);
  return [f]() {
    f->Modified();
    f->Update();
  };
}

/// The jobs whose peak memory the bench reports, each one update of a new
/// filter on a mesh: their names and how each is made.
struct MemoryJob
{
  const char* name;
  std::function<void()> (*make)(vtkPolyData* mesh);
};
const MemoryJob kMemoryJobs[] = {
  { "angle no split", [](vtkPolyData* mesh) { return ours(mesh, slPolyDataNormals::ANGLE, false); } },
  { "split+cons", [](vtkPolyData* mesh) { return ours(mesh, slPolyDataNormals::ANGLE, true); } },
  { "vtkTriangleMeshPointNormals",
    [](vtkPolyData* mesh) {
      return std::function<void()>([mesh] {
        vtkNew<vtkTriangleMeshPointNormals> f;
        f->SetInputData(mesh);
        f->Update();
      });
    } },
};
constexpr int kMemoryJobCount = static_cast<int>(sizeof(kMemoryJobs) / sizeof(kMemoryJobs[0]));

/// The torus of @p millions million triangles, shuffled or not, exactly as
/// the bench makes it.
vtkSmartPointer<vtkPolyData> benchMesh(double millions, bool shuffled)
{
  vtkSmartPointer<vtkPolyData> torus = slBenchTorus(static_cast<long long>(millions * 1e6));
  return shuffled ? slBenchShuffled(torus, 1) : torus;
}

constexpr const char* kMemoryJobOption = "--memory-job";

/// In a process of its own (`--memory-job MILLIONS ORDER JOB THREADS`):
/// builds the mesh, runs the job once on a small torus (so that code pages
/// and the thread pool are in place, as in a program that has run the
/// filter before), then prints the job's peak memory above what the
/// process held before it, in bytes.
int runMemoryJob(char** argv)
{
  const double millions = std::atof(argv[2]);
  const bool shuffled = std::string(argv[3]) == "shuffled";
  const int which = std::atoi(argv[4]);
  vtkSMPTools::Initialize(std::atoi(argv[5]));
  if (which < 0 || which >= kMemoryJobCount)
  {
    return 2;
  }
  {
    vtkSmartPointer<vtkPolyData> small = slBenchTorus(20000);
    kMemoryJobs[which].make(small)();
  }
  vtkSmartPointer<vtkPolyData> mesh = benchMesh(millions, shuffled);
  std::printf("%lld\n", slPeakMemoryAbove(kMemoryJobs[which].make(mesh)));
  return 0;
}

/// The peak memory of every memory job above @p inputBytes, each measured
/// in a new process of this program: what earlier jobs left in this
/// process's allocator cannot change it. " NAME 0.42x;" per job.
std::string memoryInNewProcesses(double millions, bool shuffled, int threads, double inputBytes)
{
  char self[4096];
  const ssize_t length = readlink("/proc/self/exe", self, sizeof(self) - 1);
  self[length > 0 ? length : 0] = '\0';
  std::string text;
  for (int which = 0; which < kMemoryJobCount; ++which)
  {
    long long peak = -1;
    if (length > 0)
    {
      char command[4200];
      std::snprintf(command, sizeof(command), "'%s' %s %.17g %s %d %d", self, kMemoryJobOption, millions,
        shuffled ? "shuffled" : "ordered", which, threads);
      if (FILE* child = popen(command, "r"))
      {
        if (std::fscanf(child, "%lld", &peak) != 1)
        {
          peak = -1;
        }
        if (pclose(child) != 0)
        {
          peak = -1;
        }
      }
    }
    char cell[96];
    if (peak < 0)
    {
      std::snprintf(cell, sizeof(cell), " %s (not measured);", kMemoryJobs[which].name);
    }
    else
    {
      std::snprintf(cell, sizeof(cell), " %s %.2fx;", kMemoryJobs[which].name, static_cast<double>(peak) / inputBytes);
    }
    text += cell;
  }
  return text;
}

/// Exits unless the bare loop's sums point along slPolyDataNormals' area
/// weighted normals (an independent computation of the same sums): the
/// loop the bench times must do the work it stands for.
void checkBareLoop(vtkPolyData* mesh, slBenchBareLoop& bare, int threads)
{
  vtkNew<slPolyDataNormals> area;
  area->SetInputData(mesh);
  area->SetWeighting(slPolyDataNormals::AREA);
  area->SetSplitting(false);
  area->SetConsistency(false);
  area->Update();
  bare.Run(threads);
  const double degrees = bare.LargestAngleTo(area->GetOutput()->GetPointData()->GetNormals());
  std::printf("   bare loop: each triangle's points read, their cross product added at them (no checks, weights, "
              "normalising); largest angle to slPolyDataNormals area %.1e deg\n",
    degrees);
  if (!(degrees < 1e-2))
  {
    std::fprintf(stderr, "shadelab_bench_normals: the bare loop's sums are wrong (%g deg)\n", degrees);
    std::exit(1);
  }
}

Result benchOne(vtkPolyData* mesh, bool shuffled, const std::string& label, const std::string& memory, int runs,
  int threads, const BenchMachine& machine)
{
  const double tris = static_cast<double>(mesh->GetNumberOfPolys());
  const double points = static_cast<double>(mesh->GetNumberOfPoints());
  vtkCellArray* cells = mesh->GetPolys();
  const double idBytes = cells->IsStorage64Bit() ? 8 : 4;
  const double inputBytes = idBytes * (cells->GetNumberOfConnectivityIds() + cells->GetNumberOfOffsets()) +
    12.0 * points;
  // The least a pass must move: read the polygons and points, write the
  // normals (no split); with splitting also write the split points and
  // 32-bit polygons (measured output size).
  const double gbs = machine.bandwidthAllThreads;
  const double floorPlain = (inputBytes + 12.0 * points) / (gbs * 1e9);

  vtkNew<slPolyDataNormals> check;
  check->SetInputData(mesh);
  check->Update();
  const double splitPoints = static_cast<double>(check->GetOutput()->GetNumberOfPoints());
  const double floorSplit = (inputBytes + 24.0 * splitPoints +
                              4.0 * (cells->GetNumberOfConnectivityIds() + cells->GetNumberOfOffsets())) /
    (gbs * 1e9);

  std::printf("== %s: %.0f points, %.0f triangles, %.1f MiB; medians (ranges) of %d rounds\n", label.c_str(),
    points, tris, mesh->GetActualMemorySize() / 1024.0, runs);
  std::printf("   floor (bytes a pass must move / %.1f GB/s): %.2f ms no split, %.2f ms split\n", gbs,
    floorPlain * 1e3, floorSplit * 1e3);

  vtkNew<vtkTriangleMeshPointNormals> tmpn;
  tmpn->SetInputData(mesh);
  vtkNew<vtkPolyDataNormals> pdnPlain, pdnDefault;
  pdnPlain->SetInputData(mesh);
  pdnPlain->SplittingOff();
  pdnPlain->ConsistencyOff();
  pdnDefault->SetInputData(mesh);
  slBenchOpenMesh om(mesh);
  slBenchBareLoop bare(mesh, threads, shuffled);
  auto update = [](vtkAlgorithm* a) {
    return std::function<void()>([a]() {
      a->Modified();
      a->Update();
    });
  };

  // 1. Vertex normals without splitting, all jobs once per round.
  const char* names[] = { "slPolyDataNormals angle (default)", "slPolyDataNormals angle, 1 thread",
    "slPolyDataNormals area", "vtkTriangleMeshPointNormals", "vtkPolyDataNormals (split/cons off)",
    "OpenMesh update_face+vertex_normals", "bare loop", "bare loop, 1 thread" };
  const std::vector<BenchTimes> t = timeInterleaved(runs,
    { ours(mesh, slPolyDataNormals::ANGLE, false), onOneThread(threads, ours(mesh, slPolyDataNormals::ANGLE, false)),
      ours(mesh, slPolyDataNormals::AREA, false), update(tmpn), update(pdnPlain), [&] { om.UpdateNormals(); },
      [&] { bare.Run(threads); }, onOneThread(threads, [&] { bare.Run(1); }) });
  std::printf("   vertex normals, no splitting      median ms        range ms   cpu ms  ns/tri  x floor  "
              "x TriMeshPN          x PolyDataN\n");
  for (size_t i = 0; i < t.size(); ++i)
  {
    char range[32];
    std::snprintf(range, sizeof(range), "%.1f-%.1f", t[i].minimum() * 1e3, t[i].maximum() * 1e3);
    std::printf("   %-35s %8.1f %15s %8.1f %7.1f %8.2f  %-20s %s\n", names[i], t[i].median() * 1e3, range,
      t[i].medianCpu() * 1e3, t[i].median() / tris * 1e9, t[i].median() / floorPlain,
      format(ratios(t[3], t[i], 1.5)).c_str(), format(ratios(t[4], t[i], 15)).c_str());
  }
  Result r;
  r.label = label;
  r.triangles = tris;
  r.nsPerTriangle = t[0].median() / tris * 1e9;
  r.bareNsPerTriangle = t[6].median() / tris * 1e9;
  r.overTMPN = ratios(t[3], t[0], 1.5);
  r.overPDN = ratios(t[4], t[0], 15);
  r.speedUp = ratios(t[1], t[0], 1.8);
  r.floorRatio = t[0].median() / floorPlain;
  r.overBare = ratios(t[0], t[6], 0);
  r.bareSpeedUp = ratios(t[7], t[6], 1.8);
  r.pdnOverBare = ratios(t[4], t[6], 15);
  std::printf("   speed-up of slPolyDataNormals angle from 1 to %d threads: %s; of the bare loop: %s\n", threads,
    format(r.speedUp).c_str(), format(r.bareSpeedUp).c_str());
  checkBareLoop(mesh, bare, threads);

  // 2. Splitting (30 degrees) and consistency on.
  const std::vector<BenchTimes> s =
    timeInterleaved(runs, { ours(mesh, slPolyDataNormals::ANGLE, true), update(pdnDefault) });
  r.splitOverPDN = ratios(s[1], s[0], 10);
  r.splitFloorRatio = s[0].median() / floorSplit;
  std::printf("   splitting 30 deg + consistency    median ms        range ms   cpu ms  ns/tri  x floor  "
              "x PolyDataN defaults   output points\n");
  const char* splitNames[] = { "slPolyDataNormals (defaults)", "vtkPolyDataNormals (defaults)" };
  const double splitOut[] = { splitPoints, static_cast<double>(pdnDefault->GetOutput()->GetNumberOfPoints()) };
  for (size_t i = 0; i < s.size(); ++i)
  {
    char range[32];
    std::snprintf(range, sizeof(range), "%.1f-%.1f", s[i].minimum() * 1e3, s[i].maximum() * 1e3);
    std::printf("   %-35s %8.1f %15s %8.1f %7.1f %8.2f  %-20s %.0f\n", splitNames[i], s[i].median() * 1e3, range,
      s[i].medianCpu() * 1e3, s[i].median() / tris * 1e9, s[i].median() / floorSplit,
      format(ratios(s[1], s[i], 10)).c_str(), splitOut[i]);
  }

  std::printf("   peak memory above the input:%s\n\n", memory.c_str());
  return r;
}
} // namespace

int main(int argc, char** argv)
{
  if (argc == 6 && std::string(argv[1]) == kMemoryJobOption)
  {
    return runMemoryJob(argv);
  }
  BenchArguments args("shadelab_bench_normals",
    "slPolyDataNormals against vtkTriangleMeshPointNormals, vtkPolyDataNormals and OpenMesh on generated tori", 5);
  std::vector<double> sizes = { 0.1, 0.5, 2, 8 };
  args.text("sizes", "LIST", "millions of triangles, comma-separated (default 0.1,0.5,2,8)",
    [&](const std::string& v) { return parseSizes(v, sizes); });
  std::string order = "both";
  args.text("order", "ORDER", "ordered, shuffled (points and triangles in random order) or both (default)",
    [&](const std::string& v) {
      order = v;
      return v == "ordered" || v == "shuffled" || v == "both" ? "" : "'" + v + "' is not ordered, shuffled or both";
    });
  if (!args.parse(argc, argv))
  {
    return args.exitCode();
  }
  const BenchMachine machine = BenchMachine::measure();
  machine.print();
  const int threads = machine.threads;
  std::vector<Result> results;
  for (double millions : sizes)
  {
    char size[32];
    std::snprintf(size, sizeof(size), "%gM triangles", millions);
    for (bool shuffled : { false, true })
    {
      if (order == (shuffled ? "ordered" : "shuffled"))
      {
        continue;
      }
      // Peak memory first, each job in a new process that builds the same
      // mesh, before any filter is timed here.
      vtkSmartPointer<vtkPolyData> mesh = benchMesh(millions, shuffled);
      const std::string memory = memoryInNewProcesses(
        millions, shuffled, threads, static_cast<double>(mesh->GetActualMemorySize()) * 1024.0);
      results.push_back(benchOne(mesh, shuffled, std::string(size) + (shuffled ? ", shuffled" : ", ordered"), memory,
        args.runs(), threads, machine));
    }
  }

  std::printf("summary (slPolyDataNormals angle; ratios: median (range) of per-round ratios, rounds at the goal)\n");
  std::printf("%-26s %7s %8s %-26s %-26s %-26s %-26s %8s  %-20s %-26s %s\n", "mesh", "ns/tri", "x floor",
    "x TriMeshPN (>=1.5)", "x PolyDataN (>=15)", "split x PolyDataN (>=10)", "1->N threads (>=1.8)", "split x floor",
    "x bare loop", "bare 1->N (>=1.8)", "PolyDataN / bare (>=15)");
  for (const Result& r : results)
  {
    auto cell = [](const Spread& s) {
      return format(s) + " " + std::to_string(s.reaching) + "/" + std::to_string(s.of);
    };
    std::printf("%-26s %7.2f %8.2f %-26s %-26s %-26s %-26s %8.2f  %-20s %-26s %s\n", r.label.c_str(),
      r.nsPerTriangle, r.floorRatio, cell(r.overTMPN).c_str(), cell(r.overPDN).c_str(), cell(r.splitOverPDN).c_str(),
      cell(r.speedUp).c_str(), r.splitFloorRatio, format(r.overBare).c_str(), cell(r.bareSpeedUp).c_str(),
      cell(r.pdnOverBare).c_str());
  }
  // Cost per triangle of the largest mesh against the one just below (goal
  // <= 1.2), and the bare loop's: how much of the growth no pass escapes.
  for (const char* kind : { "ordered", "shuffled" })
  {
    const Result *largest = nullptr, *below = nullptr;
    for (const Result& r : results)
    {
      if (r.label.find(kind) == std::string::npos)
      {
        continue;
      }
      if (!largest || r.triangles > largest->triangles)
      {
        below = largest;
        largest = &r;
      }
      else if (!below || r.triangles > below->triangles)
      {
        below = &r;
      }
    }
    if (largest && below)
    {
      std::printf("ns/triangle %s, %s against %s: %.2f (goal <= 1.2); bare loop %.2f\n", kind,
        largest->label.c_str(), below->label.c_str(), largest->nsPerTriangle / below->nsPerTriangle,
        largest->bareNsPerTriangle / below->bareNsPerTriangle);
    }
  }
  return 0;
}
