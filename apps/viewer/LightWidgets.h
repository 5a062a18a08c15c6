#ifndef shadelab_viewer_LightWidgets_h
#define shadelab_viewer_LightWidgets_h
/**
 * @class   LightWidgets
 * @brief   The scene's lights drawn in the view as VTK light widgets (a
 *          sphere at the light, a line to where it points, a cone for spots)
 *          that move the lights when dragged.
 *
 * Directional lights sit outside the mesh on their direction and aim at the
 * mesh's centre: dragging the sphere turns the light. Point lights move with
 * their sphere. Spots move with their sphere, aim with the far end of the
 * line and widen or narrow with the cone. Camera lights are shown where the
 * current camera puts them and written back in camera space, so they keep
 * following the camera. Ambient lights have no place and no widget.
 *
 * @sa vtkLightWidget vtkLightRepresentation shadelab::lightInCameraSpace
 */

#include "shadelab/Scene.h"

#include <vtkSmartPointer.h>

#include <vector>

class vtkCamera;
class vtkLightWidget;
class vtkObject;
class vtkRenderer;
class vtkRenderWindowInteractor;

namespace shadelab
{
namespace viewer
{
class ViewerDocument;

/// @p light in @p space for the view's @p camera: the same light at the same
/// place, its position and direction converted by shadelab::lightInWorldSpace()
/// and shadelab::lightInCameraSpace() (the renderer's camera-light space). A
/// light already in @p space is returned as it is.
SceneLight lightInSpace(const SceneLight& light, LightSpace space, vtkCamera* camera);

class LightWidgets
{
public:
  explicit LightWidgets(ViewerDocument* document);
  ~LightWidgets();

  /// Shows one widget per light in @p renderer, sized and placed for a
  /// mesh with @p bounds (xmin, xmax, ymin, ymax, zmin, zmax).
  void attach(vtkRenderWindowInteractor* interactor, vtkRenderer* renderer, const double bounds[6]);
  /// Removes every widget.
  void detach();
  /// Moves the widgets to where the scene's lights are now (after an edit in
  /// a panel, or a camera move for camera lights). Does nothing while a
  /// widget is being dragged.
  void sync();
  /// Whether widgets are shown at all.
  void setEnabled(bool enabled);
  bool enabled() const { return this->Enabled; }
  /// How many widgets are shown (one per non-ambient light).
  int count() const { return static_cast<int>(this->Widgets.size()); }
  /// Widget @p i (0 <= i < count()), and the index of its light in the scene.
  vtkLightWidget* widget(int i) const;
  int lightOf(int i) const { return this->LightOfWidget[static_cast<size_t>(i)]; }

private:
  LightWidgets(const LightWidgets&) = delete;
  void operator=(const LightWidgets&) = delete;
  void build();
  void onInteraction(vtkObject* caller, unsigned long event, void* data);

  ViewerDocument* Document;
  vtkRenderWindowInteractor* Interactor = nullptr;
  vtkRenderer* Renderer = nullptr;
  double Centre[3] = { 0.0, 0.0, 0.0 };
  double Size = 1.0;
  bool Enabled = true;
  bool Dragging = false;
  std::vector<vtkSmartPointer<vtkLightWidget>> Widgets;
  std::vector<int> LightOfWidget; ///< index into the scene's lights
};

} // namespace viewer
} // namespace shadelab

#endif
