#include "slLightingSetup.h"

#include "shadelab/DefaultScene.h"
#include "shadelab/Scene.h"
#include "shadelab/SceneLimits.h"
#include "slScene.h"

#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkRenderer.h>

namespace shadelab
{

namespace
{
glm::vec3 toVec3(const double v[3])
{
  return glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
}
} // namespace

LightingSetup makeLightingSetup(slScene* scene, vtkLightCollection* lights, vtkProperty* property,
  vtkCamera* camera, const double bounds[6])
{
  vtkNew<slScene> merged;
  merged->SetScene(scene ? scene->GetScene() : defaultScene());
  if (lights)
  {
    merged->SetLightsFromVTK(lights);
  }
  if (property)
  {
    merged->SetMaterialFromVTK(property);
  }
  if (camera)
  {
    merged->SetCameraFromVTK(camera);
  }
  const Scene& s = merged->GetScene();
  LightingSetup setup;
  setup.problem = sceneValueProblem(s);
  if (!setup.problem.empty())
  {
    return setup;
  }

  // Place the camera as the renderer would (fitting the mesh when the scene
  // gives no position), then read the eye back.
  vtkNew<vtkRenderer> renderer;
  merged->ApplyCamera(renderer);
  vtkCamera* placed = renderer->GetActiveCamera();
  if (!s.camera.hasPosition && bounds && bounds[0] <= bounds[1])
  {
    double b[6] = { bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5] };
    placed->SetPosition(0.0, 0.0, 1.0);
    placed->SetFocalPoint(0.0, 0.0, 0.0);
    renderer->ResetCamera(b);
    placed->Azimuth(s.camera.azimuth);
    placed->Elevation(s.camera.elevation);
    placed->OrthogonalizeViewUp();
  }

  setup.eye = toVec3(placed->GetPosition());
  const glm::vec3 focal = toVec3(placed->GetFocalPoint());
  const glm::vec3 up = toVec3(placed->GetViewUp());
  for (size_t i = 0; i < s.lights.size(); ++i)
  {
    setup.lights.push_back(toEvaluationLight(lightInWorldSpace(s.lights[i], setup.eye, focal, up)));
    setup.names.push_back(s.lights[i].name.empty() ? "light" + std::to_string(i) : s.lights[i].name);
  }
  setup.material = toEvaluationMaterial(s.material);
  setup.model = static_cast<int>(s.model);
  return setup;
}

} // namespace shadelab
