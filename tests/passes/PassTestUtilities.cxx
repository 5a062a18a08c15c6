#include "PassTestUtilities.h"

#include "slRadianceFilter.h"
#include "slLightingPass.h"
#include "slScene.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCoordinate.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>

namespace passtest
{

float Image::luminance(int x, int y) const
{
  const float* p = this->at(x, y);
  return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
}

namespace
{
Stage makeStage(vtkPolyData* mesh, const shadelab::Scene& scene, int width, int height)
{
  Stage stage;
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  stage.actor = vtkSmartPointer<vtkActor>::New();
  stage.actor->SetMapper(mapper);
  stage.renderer = vtkSmartPointer<vtkRenderer>::New();
  stage.renderer->AddActor(stage.actor);
  stage.window = vtkSmartPointer<vtkRenderWindow>::New();
  stage.window->SetOffScreenRendering(1);
  stage.window->SetMultiSamples(0);
  stage.window->SetSize(width, height);
  stage.window->AddRenderer(stage.renderer);

  vtkNew<slScene> sceneObject;
  sceneObject->SetScene(scene);
  sceneObject->ApplyToRenderer(stage.renderer);
  return stage;
}
} // namespace

Stage litStage(vtkPolyData* mesh, const shadelab::Scene& scene, int width, int height)
{
  Stage stage = makeStage(mesh, scene, width, height);
  stage.actor->GetMapper()->ScalarVisibilityOff();
  auto sceneObject = vtkSmartPointer<slScene>::New();
  sceneObject->SetScene(scene);
  sceneObject->ApplyMaterial(stage.actor->GetProperty());
  stage.pass = vtkSmartPointer<slLightingPass>::New();
  stage.pass->SetScene(sceneObject);
  stage.renderer->SetPass(stage.pass);
  return stage;
}

Stage unlitStage(vtkPolyData* mesh, const shadelab::Scene& scene, int width, int height, bool cellScalars)
{
  Stage stage = makeStage(mesh, scene, width, height);
  auto* mapper = vtkPolyDataMapper::SafeDownCast(stage.actor->GetMapper());
  mapper->ScalarVisibilityOn();
  mapper->SetColorModeToDirectScalars();
  if (cellScalars)
  {
    mapper->SetScalarModeToUseCellData();
  }
  else
  {
    mapper->SetScalarModeToUsePointData();
  }
  stage.actor->GetProperty()->LightingOff();
  stage.actor->GetProperty()->SetInterpolationToGouraud();
  return stage;
}

Image Stage::render()
{
  this->window->Render();
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(this->window);
  capture->SetInputBufferTypeToRGB();
  capture->ReadFrontBufferOff();
  capture->Update();
  vtkImageData* data = capture->GetOutput();
  int dims[3];
  data->GetDimensions(dims);
  Image image;
  image.width = dims[0];
  image.height = dims[1];
  vtkDataArray* scalars = data->GetPointData()->GetScalars();
  image.rgb.resize(static_cast<size_t>(3) * image.width * image.height);
  for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      image.rgb[static_cast<size_t>(3 * i + c)] = static_cast<float>(scalars->GetComponent(i, c) / 255.0);
    }
  }
  return image;
}

void Stage::toDisplay(const double world[3], double display[2])
{
  vtkNew<vtkCoordinate> coordinate;
  coordinate->SetCoordinateSystemToWorld();
  coordinate->SetValue(world[0], world[1], world[2]);
  const double* d = coordinate->GetComputedDoubleDisplayValue(this->renderer);
  display[0] = d[0];
  display[1] = d[1];
}

void colourPointsOnCPU(vtkPolyData* mesh, const shadelab::Scene& scene)
{
  // The CPU lighting filter's Radiance, as the proof asks.
  vtkNew<slScene> sceneObject;
  sceneObject->SetScene(scene);
  vtkNew<slRadianceFilter> radiance;
  radiance->SetScene(sceneObject);
  radiance->SetInputData(mesh);
  radiance->Update();
  vtkDataArray* values = radiance->GetOutput()->GetPointData()->GetArray("Radiance");
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("CPURadiance");
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = values->GetComponent(i, c);
      colours->SetValue(3 * i + c, static_cast<unsigned char>(std::lround(255.0 * std::min(1.0, std::max(0.0, v)))));
    }
  }
  mesh->GetPointData()->SetScalars(colours);
}

std::vector<bool> interiorMask(const Image& image, const glm::vec3& background)
{
  auto covered = [&](int x, int y) {
    const float* p = image.at(x, y);
    return std::abs(p[0] - background.x) + std::abs(p[1] - background.y) + std::abs(p[2] - background.z) > 1.5f / 255.0f;
  };
  std::vector<bool> mask(static_cast<size_t>(image.width) * image.height, false);
  for (int y = 1; y + 1 < image.height; ++y)
  {
    for (int x = 1; x + 1 < image.width; ++x)
    {
      bool all = true;
      for (int dy = -1; dy <= 1 && all; ++dy)
      {
        for (int dx = -1; dx <= 1 && all; ++dx)
        {
          all = covered(x + dx, y + dy);
        }
      }
      mask[static_cast<size_t>(y) * image.width + x] = all;
    }
  }
  return mask;
}

Agreement agreement(const Image& a, const Image& b, const std::vector<bool>& mask)
{
  Agreement result;
  for (int y = 0; y < a.height; ++y)
  {
    for (int x = 0; x < a.width; ++x)
    {
      if (!mask[static_cast<size_t>(y) * a.width + x])
      {
        continue;
      }
      ++result.covered;
      const float* p = a.at(x, y);
      const float* q = b.at(x, y);
      const float d = std::max({ std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2]) });
      result.worst = std::max(result.worst, d);
      result.agreeing += d <= 2.0f / 255.0f + 1e-6f;
    }
  }
  return result;
}

} // namespace passtest
