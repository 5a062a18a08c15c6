// The lighting bench (issue 4): per-vertex lighting throughput of
// slRadianceFilter on a ~1M-vertex grid with 8 point lights, Blinn-Phong,
// against a vectorised numpy implementation of the same formula run in the
// same process tree by /usr/bin/python3. Prints medians and the ratio.
//
// usage: shadelab_bench_lighting [--grid N] [--repetitions R] [--no-numpy]
#include "shadelab/Scene.h"
#include "slRadianceFilter.h"
#include "slScene.h"

#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace
{
double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <typename F>
std::vector<double> timeRuns(int repetitions, F&& run)
{
  std::vector<double> seconds;
  for (int r = 0; r < repetitions; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    run();
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return seconds;
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

/// Runs the numpy version; returns its median seconds (or -1) and its first radiance.
double runNumpy(const std::string& setup, std::string& firstRadiance)
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
  }
  if (std::fgets(line, sizeof line, pipe.get()))
  {
    firstRadiance = line;
  }
  return seconds;
}
} // namespace

int main(int argc, char** argv)
{
  int grid = 1000, repetitions = 7;
  bool numpy = true;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--grid" && i + 1 < argc)
    {
      grid = std::max(2, std::atoi(argv[++i]));
    }
    else if (a == "--repetitions" && i + 1 < argc)
    {
      repetitions = std::max(1, std::atoi(argv[++i]));
    }
    else if (a == "--no-numpy")
    {
      numpy = false;
    }
    else
    {
      std::cerr << "usage: shadelab_bench_lighting [--grid N] [--repetitions R] [--no-numpy]\n";
      return 2;
    }
  }

  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1.0, -1.0, 0.0);
  plane->SetPoint1(1.0, -1.0, 0.0);
  plane->SetPoint2(-1.0, 1.0, 0.0);
  plane->SetResolution(grid - 1, grid - 1);
  plane->Update();
  vtkPolyData* mesh = plane->GetOutput();
  const shadelab::Scene scene = benchScene();
  vtkNew<slScene> slscene;
  slscene->SetScene(scene);
  vtkNew<slRadianceFilter> filter;
  filter->SetInputData(mesh);
  filter->SetScene(slscene);

  const double vertexLights = static_cast<double>(mesh->GetNumberOfPoints()) * scene.lights.size();
  std::printf("lighting bench: %lld vertices x %zu point lights, Blinn-Phong, vtkSMPTools backend %s, %d threads\n",
    static_cast<long long>(mesh->GetNumberOfPoints()), scene.lights.size(), vtkSMPTools::GetBackend(),
    vtkSMPTools::GetEstimatedNumberOfThreads());
  filter->Update(); // warm-up
  const double cpp = median(timeRuns(repetitions, [&] {
    filter->Modified();
    filter->Update();
  }));
  std::printf("slRadianceFilter: median %.4f s over %d runs = %.1f M vertex.lights/s (target >= 300)\n", cpp,
    repetitions, vertexLights / cpp * 1e-6);
  const float* r = vtkFloatArray::SafeDownCast(filter->GetOutput()->GetPointData()->GetArray("Radiance"))->GetPointer(0);
  std::printf("  first vertex Radiance: %.6g %.6g %.6g\n", r[0], r[1], r[2]);

  if (numpy)
  {
    std::string first;
    const double py = runNumpy(numpySetup(scene, grid, repetitions), first);
    if (py <= 0.0)
    {
      std::printf("numpy: could not run %s %s\n", SHADELAB_BENCH_PYTHON, SHADELAB_BENCH_NUMPY_SCRIPT);
      return 1;
    }
    std::printf("numpy (float32, vectorised): median %.4f s = %.1f M vertex.lights/s\n", py,
      vertexLights / py * 1e-6);
    std::printf("  first vertex Radiance: %s", first.c_str());
    std::printf("ratio slRadianceFilter / numpy: %.1fx (target >= 25)\n", py / cpp);
  }
  return 0;
}
