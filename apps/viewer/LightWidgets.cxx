#include "LightWidgets.h"

#include "ViewerDocument.h"

#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkLightRepresentation.h>
#include <vtkLightWidget.h>
#include <vtkProperty.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace shadelab
{
namespace viewer
{

namespace
{
glm::vec3 vec(const double v[3])
{
  return glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
}

glm::vec3 unit(const glm::vec3& v)
{
  const float length = glm::length(v);
  return length > 0.0f ? v / length : glm::vec3(0.0f, 0.0f, -1.0f);
}
} // namespace

SceneLight lightInSpace(const SceneLight& light, LightSpace space, vtkCamera* camera)
{
  if (light.space == space)
  {
    return light;
  }
  const glm::vec3 eye = vec(camera->GetPosition()), focal = vec(camera->GetFocalPoint()), up = vec(camera->GetViewUp());
  const SceneLight world = lightInWorldSpace(light, eye, focal, up);
  return space == LightSpace::Camera ? lightInCameraSpace(world, eye, focal, up) : world;
}

LightWidgets::LightWidgets(ViewerDocument* document)
  : Document(document)
{
}

LightWidgets::~LightWidgets()
{
  this->detach();
}

void LightWidgets::attach(vtkRenderWindowInteractor* interactor, vtkRenderer* renderer, const double bounds[6])
{
  this->detach();
  this->Interactor = interactor;
  this->Renderer = renderer;
  for (int i = 0; i < 3; ++i)
  {
    this->Centre[i] = 0.5 * (bounds[2 * i] + bounds[2 * i + 1]);
  }
  this->Size = std::sqrt(std::pow(bounds[1] - bounds[0], 2) + std::pow(bounds[3] - bounds[2], 2) +
    std::pow(bounds[5] - bounds[4], 2));
  if (!(this->Size > 0.0))
  {
    this->Size = 1.0;
  }
  this->build();
}

void LightWidgets::detach()
{
  for (auto& widget : this->Widgets)
  {
    widget->Off();
    widget->SetInteractor(nullptr);
  }
  this->Widgets.clear();
  this->LightOfWidget.clear();
  this->Renderer = nullptr;
  this->Interactor = nullptr;
}

vtkLightWidget* LightWidgets::widget(int i) const
{
  return this->Widgets[static_cast<size_t>(i)];
}

void LightWidgets::setEnabled(bool enabled)
{
  this->Enabled = enabled;
  for (auto& widget : this->Widgets)
  {
    widget->SetEnabled(enabled);
  }
}

void LightWidgets::build()
{
  for (auto& widget : this->Widgets)
  {
    widget->Off();
  }
  this->Widgets.clear();
  this->LightOfWidget.clear();
  if (!this->Renderer || !this->Interactor)
  {
    return;
  }
  const Scene& scene = this->Document->scene();
  for (size_t i = 0; i < scene.lights.size(); ++i)
  {
    if (!lightHasDirection(static_cast<int>(scene.lights[i].type)))
    {
      continue;
    }
    auto widget = vtkSmartPointer<vtkLightWidget>::New();
    widget->SetInteractor(this->Interactor);
    widget->SetCurrentRenderer(this->Renderer);
    widget->CreateDefaultRepresentation();
    // Drawn in the light's own colour, unlit (the lighting pass leaves
    // lighting-off actors to VTK).
    widget->GetLightRepresentation()->GetProperty()->LightingOff();
    widget->GetLightRepresentation()->SetRenderer(this->Renderer);
    widget->AddObserver(vtkCommand::InteractionEvent, this, &LightWidgets::onInteraction);
    widget->AddObserver(vtkCommand::StartInteractionEvent, this, &LightWidgets::onInteraction);
    widget->AddObserver(vtkCommand::EndInteractionEvent, this, &LightWidgets::onInteraction);
    this->Widgets.push_back(widget);
    this->LightOfWidget.push_back(static_cast<int>(i));
  }
  this->sync();
  this->setEnabled(this->Enabled);
}

void LightWidgets::sync()
{
  if (this->Dragging || !this->Renderer)
  {
    return;
  }
  const Scene& scene = this->Document->scene();
  int shown = 0;
  for (const SceneLight& light : scene.lights)
  {
    shown += lightHasDirection(static_cast<int>(light.type)) ? 1 : 0;
  }
  bool sameLights = shown == this->count();
  for (size_t w = 0; sameLights && w < this->Widgets.size(); ++w)
  {
    const int index = this->LightOfWidget[w];
    sameLights = index < static_cast<int>(scene.lights.size()) && lightHasDirection(static_cast<int>(scene.lights[index].type));
  }
  if (!sameLights)
  {
    this->build(); // build() calls sync() again with matching widgets
    return;
  }
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  const glm::vec3 centre = vec(this->Centre);
  for (size_t w = 0; w < this->Widgets.size(); ++w)
  {
    const SceneLight world =
      lightInSpace(scene.lights[static_cast<size_t>(this->LightOfWidget[w])], LightSpace::World, camera);
    const glm::vec3 d = unit(world.direction);
    glm::vec3 position = world.position, aim = centre;
    if (!lightTakes(world.type, kLightPosition))
    {
      position = centre - d * static_cast<float>(0.45 * this->Size);
    }
    else if (lightTakes(world.type, kLightDirection))
    {
      aim = position + d * std::max(static_cast<float>(0.25 * this->Size), glm::length(centre - position));
    }
    vtkLightRepresentation* rep = this->Widgets[w]->GetLightRepresentation();
    double p[3] = { position.x, position.y, position.z }, f[3] = { aim.x, aim.y, aim.z };
    double colour[3] = { std::min(1.0f, std::max(0.2f, world.diffuse.x)), std::min(1.0f, std::max(0.2f, world.diffuse.y)),
      std::min(1.0f, std::max(0.2f, world.diffuse.z)) };
    rep->SetPositional(lightTakes(world.type, kLightCutoff));
    rep->SetLightPosition(p);
    rep->SetFocalPoint(f);
    rep->SetConeAngle(world.cutoffDegrees);
    rep->SetLightColor(colour);
  }
}

void LightWidgets::onInteraction(vtkObject* caller, unsigned long event, void*)
{
  if (event == vtkCommand::StartInteractionEvent)
  {
    this->Dragging = true;
    return;
  }
  const auto found = std::find(this->Widgets.begin(), this->Widgets.end(), caller);
  if (found == this->Widgets.end() || !this->Renderer)
  {
    return;
  }
  const size_t w = static_cast<size_t>(found - this->Widgets.begin());
  vtkLightRepresentation* rep = this->Widgets[w]->GetLightRepresentation();
  Scene scene = this->Document->scene();
  SceneLight& light = scene.lights[static_cast<size_t>(this->LightOfWidget[w])];
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  SceneLight world = lightInSpace(light, LightSpace::World, camera);
  const glm::vec3 position = vec(rep->GetLightPosition()), aim = vec(rep->GetFocalPoint());
  if (glm::length(aim - position) > 0.0f)
  {
    world.direction = unit(aim - position);
  }
  if (lightTakes(light.type, kLightPosition))
  {
    world.position = position;
  }
  if (lightTakes(light.type, kLightCutoff))
  {
    world.cutoffDegrees = static_cast<float>(std::min(90.0, std::max(0.5, rep->GetConeAngle())));
    world.edgeDegrees = std::min(world.edgeDegrees, world.cutoffDegrees);
  }
  light = lightInSpace(world, light.space, camera);
  if (event == vtkCommand::EndInteractionEvent)
  {
    this->Dragging = false;
  }
  this->Document->setScene(scene, LightsChange);
}

} // namespace viewer
} // namespace shadelab
