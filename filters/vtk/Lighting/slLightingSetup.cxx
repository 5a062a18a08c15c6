#include "slLightingSetup.h"

#include "shadelab/DefaultScene.h"
#include "shadelab/Scene.h"
#include "shadelab/SceneLimits.h"
#include "slScene.h"

#include <vtkCamera.h>
#include <vtkNew.h>

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

  // The renderers' camera rule, at the scene's image size: a fitted camera's
  // distance depends on the aspect ratio.
  vtkNew<vtkCamera> placed;
  merged->ApplyCamera(placed, bounds, 0, 0);

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
