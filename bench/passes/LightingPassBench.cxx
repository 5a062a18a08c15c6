// Frame time of slLightingPass against VTK's built-in lighting: the same
// ~2M-triangle sphere, the same three lights (directional, point, spot), the
// same 1024 x 1024 window, drawn side by side (frames interleaved) in one
// run, a run being --frames frames of each. Prints every run's medians and
// ratio, then the median and range over the runs; then what a shader variant
// switch costs on a small mesh with Mesa's shader disk cache off (every new
// variant compiled).
//
//   bash scripts/with-display.sh build/bin/shadelab_bench_pass [--help] [--runs N] [--frames N] [--threads N]
#include "BenchArguments.h"
#include "BenchMachine.h"
#include "BenchTiming.h"

#include "slLightingPass.h"
#include "slScene.h"

#include "shadelab/LightingGLSL.h"
#include "shadelab/Scene.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace
{
shadelab::Scene benchScene()
{
  shadelab::Scene s;
  s.model = shadelab::ShadingModel::Phong; // the model VTK's own lighting has
  s.frequency = shadelab::ShadingFrequency::Phong;
  s.camera.hasPosition = true;
  s.camera.position = glm::vec3(0.0f, 0.0f, 3.2f);
  shadelab::SceneLight key;
  key.direction = glm::vec3(-0.5f, -0.5f, -1.0f);
  s.lights.push_back(key);
  shadelab::SceneLight point;
  point.type = shadelab::LightType::Point;
  point.position = glm::vec3(2.0f, 1.0f, 2.0f);
  point.attenuation = glm::vec3(1.0f, 0.1f, 0.0f);
  s.lights.push_back(point);
  shadelab::SceneLight spot;
  spot.type = shadelab::LightType::Spot;
  spot.position = glm::vec3(0.0f, 2.0f, 2.0f);
  spot.direction = glm::vec3(0.0f, -1.0f, -1.0f);
  spot.cutoffDegrees = 30.0f;
  spot.exponent = 2.0f;
  s.lights.push_back(spot);
  return s;
}

/// One window drawing the mesh: VTK's lighting, or the pass when given one.
struct Setup
{
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkActor> actor;

  void build(vtkPolyData* mesh, slScene* scene, int size)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(mesh);
    this->actor->SetMapper(mapper);
    scene->ApplyMaterial(this->actor->GetProperty());
    this->renderer->AddActor(this->actor);
    scene->ApplyToRenderer(this->renderer);
    this->window->SetOffScreenRendering(1);
    this->window->SetMultiSamples(0);
    this->window->SetSize(size, size);
    this->window->AddRenderer(this->renderer);
  }

  /// Milliseconds to draw one frame, a new view each time, until the GL is done.
  double frame()
  {
    this->actor->RotateY(0.5);
    const auto start = std::chrono::steady_clock::now();
    this->window->Render();
    this->window->WaitForCompletion();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
};

std::string range(const std::vector<double>& values, const char* format)
{
  char text[64];
  std::snprintf(text, sizeof(text), format, *std::min_element(values.begin(), values.end()),
    *std::max_element(values.begin(), values.end()));
  return text;
}

/// The "OpenGL renderer string" line of the window's capabilities.
std::string rendererName(vtkRenderWindow* window)
{
  std::istringstream report(window->ReportCapabilities());
  const std::string key = "OpenGL renderer string:";
  for (std::string line; std::getline(report, line);)
  {
    if (line.compare(0, key.size(), key) == 0)
    {
      return line.substr(line.find_first_not_of(' ', key.size()));
    }
  }
  return "unknown";
}

/// What the first frame after @p change costs beyond a frame of the same
/// variant once built (the median of the next three frames).
double switchCost(Setup& setup, const std::function<void()>& change)
{
  change();
  const double first = setup.frame();
  std::vector<double> after;
  for (int i = 0; i < 3; ++i)
  {
    after.push_back(setup.frame());
  }
  return first - medianOf(after);
}
} // namespace

int main(int argc, char** argv)
{
  BenchArguments args("shadelab_bench_pass",
    "frame time of slLightingPass against VTK's built-in lighting, 2M triangles at 1024 x 1024.\n"
    "--threads also sets llvmpipe's rendering threads (LP_NUM_THREADS); without it llvmpipe uses\n"
    "one per core. Run under an X display (scripts/with-display.sh).",
    5);
  long long frames = 10, triangles = 2000000, size = 1024;
  args.integer("frames", "frames of each renderer per run (default 10)", &frames, 1, 10000);
  args.integer("triangles", "about this many triangles (default 2000000)", &triangles, 1000, 100000000);
  args.integer("size", "window width and height in pixels (default 1024)", &size, 16, 8192);
  if (!args.parse(argc, argv))
  {
    return args.exitCode();
  }
  if (args.threads() > 0)
  {
    setenv("LP_NUM_THREADS", std::to_string(args.threads()).c_str(), 1);
  }
  // Every variant built in the run is compiled, as on a first run: the switch
  // costs below are the cold ones.
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  BenchMachine::measure().print();

  const int resolution = std::max(3, static_cast<int>(std::lround(std::sqrt(triangles / 2.0))));
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution + 2);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(sphere->GetOutputPort());
  normals->SplittingOff();
  normals->Update();
  vtkPolyData* mesh = normals->GetOutput();

  vtkNew<slScene> scene;
  scene->SetScene(benchScene());
  Setup setups[2]; // 0: VTK's lighting, 1: the pass
  vtkNew<slLightingPass> pass;
  pass->SetScene(scene);
  for (Setup& s : setups)
  {
    s.build(mesh, scene, static_cast<int>(size));
  }
  setups[1].renderer->SetPass(pass);
  for (int warm = 0; warm < 2; ++warm)
  {
    setups[0].frame();
    setups[1].frame();
  }
  const char* lpThreads = std::getenv("LP_NUM_THREADS");
  std::printf("OpenGL: %s; llvmpipe threads: %s\n", rendererName(setups[0].window).c_str(),
    lpThreads ? lpThreads : "one per core (LP_NUM_THREADS unset)");
  std::printf("mesh: %lld triangles, window %lld x %lld, 3 lights (directional, point, spot), Phong model and\n"
              "frequency; %d runs of %lld frames each, interleaved\n\n",
    static_cast<long long>(mesh->GetNumberOfPolys()), size, size, args.runs(), frames);

  std::printf("run  VTK ms/frame  pass ms/frame  pass / VTK\n");
  std::vector<double> vtkRuns, passRuns, ratios;
  for (int run = 0; run < args.runs(); ++run)
  {
    std::vector<double> times[2];
    for (long long f = 0; f < frames; ++f)
    {
      for (int i = 0; i < 2; ++i)
      {
        times[i].push_back(setups[i].frame());
      }
    }
    vtkRuns.push_back(medianOf(times[0]));
    passRuns.push_back(medianOf(times[1]));
    ratios.push_back(passRuns.back() / vtkRuns.back());
    std::printf("%3d  %12.1f  %13.1f  %10.3f\n", run + 1, vtkRuns.back(), passRuns.back(), ratios.back());
    std::fflush(stdout);
  }
  const long long above105 = std::count_if(ratios.begin(), ratios.end(), [](double r) { return r > 1.05; });
  const long long above110 = std::count_if(ratios.begin(), ratios.end(), [](double r) { return r > 1.10; });
  std::printf("\nVTK built-in lighting: median %.1f ms/frame (runs %s)\n", medianOf(vtkRuns),
    range(vtkRuns, "%.1f-%.1f").c_str());
  std::printf("slLightingPass:        median %.1f ms/frame (runs %s)\n", medianOf(passRuns),
    range(passRuns, "%.1f-%.1f").c_str());
  std::printf("pass / VTK: median %.3f (runs %s); runs above 1.05: %lld, above 1.10: %lld of %d\n\n",
    medianOf(ratios), range(ratios, "%.3f-%.3f").c_str(), above105, above110, args.runs());

  // Switches on a small mesh, so that a frame is a few milliseconds and the
  // first frame of a new variant is mostly its compilation.
  vtkNew<vtkSphereSource> small;
  small->SetThetaResolution(100);
  small->SetPhiResolution(102);
  vtkNew<vtkPolyDataNormals> smallNormals;
  smallNormals->SetInputConnection(small->GetOutputPort());
  smallNormals->SplittingOff();
  smallNormals->Update();
  Setup lit;
  vtkNew<slLightingPass> switching;
  switching->SetScene(scene);
  lit.build(smallNormals->GetOutput(), scene, 256);
  lit.renderer->SetPass(switching);
  lit.frame();
  std::vector<double> models;
  for (int model : { shadelab::glsl::SL_MODEL_BLINN_PHONG, shadelab::glsl::SL_MODEL_LAMBERT,
         shadelab::glsl::SL_MODEL_PHONG_NORMALIZED, shadelab::glsl::SL_MODEL_BLINN_PHONG_NORMALIZED,
         shadelab::glsl::SL_MODEL_LAMBERT_NORMALIZED })
  {
    models.push_back(switchCost(lit, [&] { switching->SetModel(model); }));
  }
  std::printf("variant switch: the first frame minus a frame of the new variant, %lld triangles at 256 x 256,\n"
              "Mesa's shader cache off (every new variant compiled)\n",
    static_cast<long long>(smallNormals->GetOutput()->GetNumberOfPolys()));
  std::printf("  model, 5 new ones:             median %6.1f ms (%s)\n", medianOf(models),
    range(models, "%.1f-%.1f").c_str());
  std::printf("  frequency -> gouraud:                 %6.1f ms\n",
    switchCost(lit, [&] { switching->SetFrequency(slLightingPass::GOURAUD); }));
  std::printf("  frequency -> flat:                    %6.1f ms\n",
    switchCost(lit, [&] { switching->SetFrequency(slLightingPass::FLAT); }));
  std::printf("  total -> diffuse component view:      %6.1f ms\n",
    switchCost(lit, [&] { switching->SetComponent(slLightingPass::DIFFUSE); }));
  std::printf("  diffuse -> specular (a uniform):      %6.1f ms\n",
    switchCost(lit, [&] { switching->SetComponent(slLightingPass::SPECULAR); }));
  std::printf("  back to a variant built before:       %6.1f ms (VTK's shader cache)\n", switchCost(lit, [&] {
    switching->SetComponent(slLightingPass::TOTAL);
    switching->SetFrequency(slLightingPass::PHONG);
    switching->SetModel(shadelab::glsl::SL_MODEL_BLINN_PHONG);
  }));
  return 0;
}
