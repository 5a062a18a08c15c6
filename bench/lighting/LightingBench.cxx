// The lighting bench: per-vertex lighting throughput of
// slRadianceFilter on a ~1M-vertex grid with 8 point lights, Blinn-Phong,
// against a vectorised numpy implementation of the same formula run in the
// same process tree by /usr/bin/python3. Prints medians and the ratio.
//
// It also measures Monte Carlo throughput of slRadianceReference, and with
// --rmse-table prints the RMSE-against-N table of docs/lighting-cpu.md.
//
// usage: shadelab_bench_lighting [--help] [--runs N] [--threads N] [--grid N] [--no-numpy] [--no-reference]
//                                 [--rmse-table]
#include "BenchArguments.h"
#include "BenchMachine.h"
#include "BenchTiming.h"

#include "shadelab/Scene.h"
#include "slRadianceFilter.h"
#include "slRadianceReference.h"
#include "slScene.h"
#include "slUpdateOrThrow.h"

#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSphereSource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <sys/resource.h>

namespace
{
/// Wall seconds of @p repetitions calls as a user pays for one: a new
/// filter, Update(), the output arrays allocated and filled, and the filter
/// with its output freed again (no buffers carried over from the previous
/// call).
BenchTimes timeFreshUpdates(vtkPolyData* mesh, slScene* scene, int repetitions)
{
  return timeRuns(repetitions, [&] {
    vtkNew<slRadianceFilter> fresh;
    fresh->SetInputData(mesh);
    fresh->SetScene(scene);
    fresh->Update();
  });
}

/// 8 point lights above the unit grid, attenuated, coloured; Blinn-Phong.
shadelab::Scene benchScene()
{
  shadelab::Scene s;
  s.model = shadelab::ShadingModel::BlinnPhong;
  s.camera.hasPosition = true;
  s.camera.position = glm::vec3(0.3f, -0.2f, 3.0f);
  s.material.ambient = glm::vec3(0.1f);
  s.material.diffuse = glm::vec3(0.7f, 0.6f, 0.5f);
  s.material.specular = glm::vec3(0.4f);
  s.material.emission = glm::vec3(0.01f);
  s.material.shininess = 40.0f;
  for (int i = 0; i < 8; ++i)
  {
    shadelab::SceneLight l;
    l.type = shadelab::LightType::Point;
    const float a = 0.785398f * i;
    l.position = glm::vec3(1.5f * std::cos(a), 1.5f * std::sin(a), 0.5f + 0.25f * i);
    l.ambient = glm::vec3(0.02f);
    l.diffuse = glm::vec3(0.5f + 0.05f * i, 0.6f, 0.7f - 0.05f * i);
    l.specular = glm::vec3(1.0f);
    l.intensity = 0.8f;
    l.attenuation = glm::vec3(0.5f, 0.2f, 0.1f);
    s.lights.push_back(l);
  }
  return s;
}

std::string jsonVec(const glm::vec3& v)
{
  return "[" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + "]";
}

/// The bench setup as JSON for numpy_blinn_phong.py.
std::string numpySetup(const shadelab::Scene& s, int grid, int repetitions)
{
  std::string lights;
  for (const shadelab::SceneLight& l : s.lights)
  {
    lights += std::string(lights.empty() ? "" : ", ") + "{\"position\": " + jsonVec(l.position) +
      ", \"attenuation\": " + jsonVec(l.attenuation) + ", \"intensity\": " + std::to_string(l.intensity) +
      ", \"ambient\": " + jsonVec(l.ambient) + ", \"diffuse\": " + jsonVec(l.diffuse) +
      ", \"specular\": " + jsonVec(l.specular) + "}";
  }
  const shadelab::SceneMaterial& m = s.material;
  return "{\"grid\": " + std::to_string(grid) + ", \"repetitions\": " + std::to_string(repetitions) +
    ", \"eye\": " + jsonVec(s.camera.position) + ", \"lights\": [" + lights + "], \"material\": {\"ambient\": " +
    jsonVec(m.ambient) + ", \"diffuse\": " + jsonVec(m.diffuse) + ", \"specular\": " + jsonVec(m.specular) +
    ", \"emission\": " + jsonVec(m.emission) + ", \"shininess\": " + std::to_string(m.shininess) + "}}";
}

/// Runs the numpy version; returns its median wall seconds (or -1), its median
/// CPU seconds in @p cpu, and its first radiance.
double runNumpy(const std::string& setup, std::string& firstRadiance, double& cpu)
{
  const std::string path = "/tmp/shadelab-bench-lighting.json";
  std::ofstream(path) << setup;
  const std::string command = std::string(SHADELAB_BENCH_PYTHON) + " " + SHADELAB_BENCH_NUMPY_SCRIPT + " " + path;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe)
  {
    return -1.0;
  }
  char line[256];
  double seconds = -1.0;
  if (std::fgets(line, sizeof line, pipe.get()))
  {
    seconds = std::atof(line);
    const char* space = std::strchr(line, ' ');
    cpu = space ? std::atof(space + 1) : -1.0;
  }
  if (std::fgets(line, sizeof line, pipe.get()))
  {
    firstRadiance = line;
  }
  return seconds;
}
const std::string kEnvironment = std::string(SHADELAB_DATA_DIR) + "/envmaps/venice_sunset_1k.hdr";

vtkSmartPointer<vtkPolyData> sphereMesh(int resolution)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution);
  sphere->Update();
  vtkSmartPointer<vtkPolyData> mesh = sphere->GetOutput();
  return mesh;
}

/// A Blinn-Phong-normalised material under the bench's first two lights.
vtkSmartPointer<slScene> referenceScene()
{
  shadelab::Scene s = benchScene();
  s.lights.resize(2);
  s.model = shadelab::ShadingModel::BlinnPhongNormalized;
  auto scene = vtkSmartPointer<slScene>::New();
  scene->SetScene(s);
  return scene;
}

vtkSmartPointer<vtkPolyData> runReference(vtkPolyData* mesh, int strategy, int samples, int seed, bool lights = true)
{
  vtkNew<slRadianceReference> reference;
  reference->SetUseSceneLights(lights);
  reference->SetInputData(mesh);
  reference->SetScene(referenceScene());
  reference->SetEnvironmentFileName(kEnvironment.c_str());
  reference->SetStrategy(strategy);
  reference->SetSamplesPerPoint(samples);
  reference->SetSeed(seed);
  try
  {
    slUpdateOrThrow(reference);
  }
  catch (const shadelab::Error& e)
  {
    std::fprintf(stderr, "%s\n", e.what());
    std::exit(1);
  }
  vtkSmartPointer<vtkPolyData> out = reference->GetOutput();
  return out;
}

/// Monte Carlo throughput: samples (estimator evaluations) per second, per strategy.
void monteCarloThroughput(int repetitions)
{
  vtkSmartPointer<vtkPolyData> mesh = sphereMesh(100);
  const char* names[] = { "uniform", "cosine", "brdf", "light", "mis" };
  const int samples = 64;
  for (int strategy = 0; strategy <= 4; ++strategy)
  {
    const double seconds =
      timeRuns(std::max(3, repetitions / 2), [&] { runReference(mesh, strategy, samples, 1); }).median();
    const double perIteration = strategy == 4 ? 2.0 : 1.0; // MIS draws a BRDF and a light sample
    std::printf("slRadianceReference %-7s: %lld points x %d: median %.3f s = %.2f M samples/s\n", names[strategy],
      static_cast<long long>(mesh->GetNumberOfPoints()), samples, seconds,
      mesh->GetNumberOfPoints() * samples * perIteration / seconds * 1e-6);
  }
}

/// RMSE of the green channel against a 16384-sample MIS estimate, over the
/// points of a small sphere and 4 seeds, for N = 4 ... 1024.
void rmseTable(bool lights)
{
  vtkSmartPointer<vtkPolyData> mesh = sphereMesh(16);
  vtkSmartPointer<vtkPolyData> truth = runReference(mesh, 4, 16384, 12345, lights);
  vtkDataArray* t = truth->GetPointData()->GetArray("Radiance");
  std::printf("\nRMSE, %s, %lld points x 4 seeds\n", lights ? "environment + 2 spherical lights" : "environment only",
    static_cast<long long>(mesh->GetNumberOfPoints()));
  std::printf("| N | uniform | cosine | brdf | light | mis |\n|---|---|---|---|---|---|\n");
  for (int n = 4; n <= 1024; n *= 4)
  {
    std::printf("| %d |", n);
    for (int strategy = 0; strategy <= 4; ++strategy)
    {
      double sum = 0.0;
      vtkIdType count = 0;
      for (int seed = 1; seed <= 4; ++seed)
      {
        vtkSmartPointer<vtkPolyData> out = runReference(mesh, strategy, n, seed, lights);
        vtkDataArray* r = out->GetPointData()->GetArray("Radiance");
        for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
        {
          const double d = r->GetComponent(i, 1) - t->GetComponent(i, 1);
          sum += d * d;
          ++count;
        }
      }
      std::printf(" %.4g |", std::sqrt(sum / count));
    }
    std::printf("\n");
  }
}
} // namespace

int main(int argc, char** argv)
{
  BenchArguments args("shadelab_bench_lighting",
    "slRadianceFilter (Blinn-Phong, 8 point lights) against vectorised numpy, and Monte Carlo throughput",
    7);
  long long grid = 1000;
  bool noNumpy = false, noReference = false, table = false;
  args.integer("grid", "grid of N x N vertices (default 1000)", &grid, 2, 10000);
  args.flag("no-numpy", "skip the numpy peer", &noNumpy);
  args.flag("no-reference", "skip the Monte Carlo throughput", &noReference);
  args.flag("rmse-table", "also print the Monte Carlo RMSE tables (~40 s)", &table);
  if (!args.parse(argc, argv))
  {
    return args.exitCode();
  }
  const int repetitions = args.runs();
  BenchMachine::measure().print();

  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1.0, -1.0, 0.0);
  plane->SetPoint1(1.0, -1.0, 0.0);
  plane->SetPoint2(-1.0, 1.0, 0.0);
  plane->SetResolution(static_cast<int>(grid) - 1, static_cast<int>(grid) - 1);
  plane->Update();
  vtkPolyData* mesh = plane->GetOutput();
  const shadelab::Scene scene = benchScene();
  vtkNew<slScene> slscene;
  slscene->SetScene(scene);
  vtkNew<slRadianceFilter> filter;
  filter->SetInputData(mesh);
  filter->SetScene(slscene);

  const double vertexLights = static_cast<double>(mesh->GetNumberOfPoints()) * scene.lights.size();
  std::printf("lighting bench: %lld vertices x %zu point lights, Blinn-Phong\n",
    static_cast<long long>(mesh->GetNumberOfPoints()), scene.lights.size());
  filter->Update(); // warm-up
  const BenchTimes filterTimes = timeFreshUpdates(mesh, slscene, repetitions);
  const double cpp = filterTimes.median();
  const double cppCpu = filterTimes.medianCpu();
  std::printf("slRadianceFilter: median %.4f s (range %.4f-%.4f) over %d runs = %.1f M vertex.lights/s\n", cpp,
    filterTimes.minimum(), filterTimes.maximum(), repetitions, vertexLights / cpp * 1e-6);
  std::printf("  CPU time: median %.4f s (all threads) = %.1f M vertex.lights per CPU second\n", cppCpu,
    vertexLights / cppCpu * 1e-6);
  // A whole shininess (40 above) takes pow by repeated squaring; a fraction
  // takes exp2(y log2 x). Both are printed so neither figure hides the other.
  shadelab::Scene fractional = scene;
  fractional.material.shininess += 0.5f;
  vtkNew<slScene> fractionalScene;
  fractionalScene->SetScene(fractional);
  const double cppFractional = timeFreshUpdates(mesh, fractionalScene, repetitions).median();
  std::printf("  with shininess %g (pow as exp2(y log2 x)): median %.4f s = %.1f M vertex.lights/s\n",
    fractional.material.shininess, cppFractional, vertexLights / cppFractional * 1e-6);
  const float* r = vtkFloatArray::SafeDownCast(filter->GetOutput()->GetPointData()->GetArray("Radiance"))->GetPointer(0);
  std::printf("  first vertex Radiance: %.6g %.6g %.6g\n", r[0], r[1], r[2]);

  if (!noNumpy)
  {
    std::string first;
    double pyCpu = -1.0;
    const double py = runNumpy(numpySetup(scene, static_cast<int>(grid), repetitions), first, pyCpu);
    if (py <= 0.0)
    {
      std::printf("numpy: could not run %s %s\n", SHADELAB_BENCH_PYTHON, SHADELAB_BENCH_NUMPY_SCRIPT);
      return 1;
    }
    std::printf("numpy (float32, vectorised): median %.4f s = %.1f M vertex.lights/s\n", py,
      vertexLights / py * 1e-6);
    std::printf("  first vertex Radiance: %s", first.c_str());
    std::printf("ratio slRadianceFilter / numpy: %.1fx\n", py / cpp);
    if (pyCpu > 0.0)
    {
      const int threads = vtkSMPTools::GetEstimatedNumberOfThreads();
      std::printf("  numpy CPU time: median %.4f s; wall-clock ratio on an idle machine would be about\n"
                  "  %.1fx (numpy's CPU time / the filter's CPU time shared over %d threads)\n",
        pyCpu, pyCpu / (cppCpu / threads), threads);
    }
  }
  if (!noReference)
  {
    monteCarloThroughput(repetitions);
  }
  if (table)
  {
    rmseTable(false);
    rmseTable(true);
  }
  return 0;
}
