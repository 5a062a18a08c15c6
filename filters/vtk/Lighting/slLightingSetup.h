#ifndef slLightingSetup_h
#define slLightingSetup_h
/**
 * @file slLightingSetup.h
 * @brief Internal: the lights (world space), material, model and eye a
 * lighting filter evaluates, gathered from an slScene and/or VTK's own
 * vtkLightCollection, vtkProperty and vtkCamera. Not wrapped.
 */

#include "shadelab/LightingGLSL.h"

#include <string>
#include <vector>

class slScene;
class vtkCamera;
class vtkLightCollection;
class vtkProperty;

namespace shadelab
{

struct LightingSetup
{
  std::vector<glsl::slLight> lights; ///< world space, ready for slShadeLight()
  std::vector<std::string> names;    ///< one per light: the scene name or "light<i>"
  glsl::slMaterial material;
  int model = glsl::SL_MODEL_BLINN_PHONG;
  glm::vec3 eye{ 0.0f, 0.0f, 1.0f };
  /// "" or the first value of the merged scene out of range or not finite
  /// (sceneValueProblem): lights, materials and cameras from VTK objects or
  /// code are not checked anywhere else.
  std::string problem;
};

/// Builds the setup. @p scene may be null (ShadeLab's default scene); each
/// non-null VTK object replaces the scene's lights, material or camera.
/// The eye is that of slScene::ApplyCamera() for @p bounds (xmin, xmax, ymin,
/// ...; those of the whole mesh) and the scene's image size, the camera the
/// renderers draw with.
LightingSetup makeLightingSetup(slScene* scene, vtkLightCollection* lights, vtkProperty* property,
  vtkCamera* camera, const double bounds[6]);

} // namespace shadelab

#endif
