// Frame time of slLightingPass against VTK's built-in lighting: the same
// ~2M-triangle mesh, the same lights, the same 1024 x 1024 window, measured
// side by side (frames interleaved) in one run. Prints medians and the ratio.
//
//   bash scripts/with-display.sh build/bin/shadelab_bench_pass [--help] [--runs FRAMES]
#include "BenchArguments.h"
#include "BenchMachine.h"
#include "BenchTiming.h"

#include "slLightingPass.h"
#include "slScene.h"

#include "shadelab/Scene.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
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
} // namespace

int main(int argc, char** argv)
{
  BenchArguments args("shadelab_bench_pass",
    "frame time of slLightingPass against VTK's built-in lighting, 2M triangles at 1024 x 1024", 15);
  if (!args.parse(argc, argv))
  {
    return args.exitCode();
  }
  const int frames = args.runs();
  BenchMachine::measure().print();
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(1000);
  sphere->SetPhiResolution(1002);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(sphere->GetOutputPort());
  normals->SplittingOff();
  normals->Update();
  vtkPolyData* mesh = normals->GetOutput();
  std::printf("mesh: %lld triangles, window 1024 x 1024, %d frames each\n",
    static_cast<long long>(mesh->GetNumberOfPolys()), frames);

  vtkNew<slScene> scene;
  scene->SetScene(benchScene());

  struct Setup
  {
    vtkNew<vtkRenderWindow> window;
    vtkNew<vtkRenderer> renderer;
    vtkNew<vtkActor> actor;
  };
  Setup setups[2];
  vtkNew<slLightingPass> pass;
  pass->SetScene(scene);
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(mesh);
    setups[i].actor->SetMapper(mapper);
    scene->ApplyMaterial(setups[i].actor->GetProperty());
    setups[i].renderer->AddActor(setups[i].actor);
    scene->ApplyToRenderer(setups[i].renderer);
    setups[i].window->SetOffScreenRendering(1);
    setups[i].window->SetMultiSamples(0);
    setups[i].window->SetSize(1024, 1024);
    setups[i].window->AddRenderer(setups[i].renderer);
  }
  setups[1].renderer->SetPass(pass);

  std::vector<double> times[2];
  for (int f = -2; f < frames; ++f) // two warm-up frames each
  {
    for (int i = 0; i < 2; ++i)
    {
      setups[i].actor->RotateY(0.5); // a new view each frame
      const auto start = std::chrono::steady_clock::now();
      setups[i].window->Render();
      setups[i].window->WaitForCompletion();
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      if (f >= 0)
      {
        times[i].push_back(ms);
      }
    }
  }
  const double vtk = medianOf(times[0]), ours = medianOf(times[1]);
  const auto range = [](const std::vector<double>& t) {
    char text[48];
    std::snprintf(text, sizeof(text), "%.1f-%.1f", *std::min_element(t.begin(), t.end()),
      *std::max_element(t.begin(), t.end()));
    return std::string(text);
  };
  std::printf("VTK built-in lighting: median %.1f ms/frame (range %s)\n", vtk, range(times[0]).c_str());
  std::printf("slLightingPass:        median %.1f ms/frame (range %s)\n", ours, range(times[1]).c_str());
  std::printf("ratio pass / VTK: %.3f\n", ours / vtk);
  return 0;
}
