#ifndef shadelab_viewer_SceneView_h
#define shadelab_viewer_SceneView_h
/**
 * @class   SceneView
 * @brief   shadelab-viewer's 3D view: the document's mesh lit by ShadeLab's
 *          render pass, flat | Gouraud | Phong side by side, or a field
 *          colour-mapped with its scalar bar.
 *
 * Each panel is built by slSceneRenderer::Prepare(), the very code `shadelab
 * render` runs, and shown in this Qt window instead of an offscreen one: the
 * same scene file gives the same pixels (a test checks it). Material and
 * light edits only change uniforms and re-render; model and frequency edits
 * select another shader variant; mesh and normals edits rebuild the panels.
 * All panels share one camera, so the split view's cameras are linked.
 *
 * The scene's lights are drawn as draggable widgets (LightWidgets), normals
 * can be drawn as line glyphs, and a click can pick a mesh point for the
 * BRDF panel. Multisampling is off, as in offscreen rendering.
 *
 * @sa slSceneRenderer slFieldImageRenderer LightWidgets ViewerDocument
 */

#include <QVTKOpenGLNativeWidget.h>

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <QString>

#include <string>

#include <memory>
#include <vector>

class slScene;
class slLightingPass;
class slSceneRenderer;
class vtkActor;
class vtkCamera;
class vtkImageData;
class vtkObject;
class vtkPolyData;
class vtkRenderer;

namespace shadelab
{
namespace viewer
{
class LightWidgets;
class ViewerDocument;

class SceneView : public QVTKOpenGLNativeWidget
{
  Q_OBJECT
public:
  enum Mode
  {
    LitMode,   ///< the scene as `shadelab render` draws it
    SplitMode, ///< flat | Gouraud | Phong, linked cameras
    FieldMode  ///< a field of fieldMesh() colour-mapped, with a scalar bar
  };

  explicit SceneView(ViewerDocument* document, QWidget* parent = nullptr);
  ~SceneView() override;

  void setMode(Mode mode);
  Mode mode() const { return this->CurrentMode; }

  /// The lighting pass of lit panel @p i, or null (for tests: its shader builds).
  slLightingPass* lightingPass(int i = 0) const;

  /// Field mode shows point (or cell) array @p arrayName of @p mesh.
  void setField(vtkPolyData* mesh, const QString& arrayName);
  QString fieldName() const { return this->FieldName; }
  /// The mesh whose field is shown, or null.
  vtkPolyData* fieldMesh() const;

  /// Normals as line glyphs (length 3% of the mesh's diagonal).
  void setNormalGlyphs(bool shown);
  /// Light widgets on or off.
  void setLightWidgets(bool shown);
  LightWidgets* lightWidgets() const { return this->Widgets.get(); }
  /// A surface drawn with the mesh, lit like it (the BRDF lobe); null: none.
  void setLobe(vtkPolyData* lobe);
  /// While on, a left click on the mesh picks a point instead of rotating.
  void setPicking(bool on);
  /// Picks the surface under display position (x, y) (pixels, origin at the
  /// bottom left) and emits pointPicked. False if the mesh is not there.
  bool pickAt(int x, int y);

  /// The camera every panel shares.
  vtkCamera* camera() const;
  /// The mesh with the normals the view lights it with (computed with the
  /// document's normals settings, also when the view shows flat shading):
  /// what fields, glyphs and lobes are computed on. Null without a mesh.
  vtkPolyData* meshWithNormals();
  /// The panels' renderers (one, or three in split mode).
  const std::vector<vtkSmartPointer<vtkRenderer>>& renderers() const { return this->Renderers; }

  /// Renders and captures the view without the light widgets: RGB, unsigned
  /// char, row 0 at the bottom.
  vtkSmartPointer<vtkImageData> grabImage();
  /// Renders now (QWidget::update() only schedules a paint).
  void renderNow();

signals:
  /// A surface point picked with the mouse, in world coordinates.
  void pointPicked(double x, double y, double z);
  void problem(const QString& message);

private:
  void rebuild(bool keepCamera);
  void buildLitPanels();
  void buildFieldPanel();
  void addNormalGlyphs(vtkRenderer* renderer);
  void onSceneChanged(int changes);
  void onCameraModified(vtkObject*, unsigned long, void*);
  bool onLeftButton(vtkObject*, unsigned long, void*);
  void report(const QString& message);

  ViewerDocument* Document;
  Mode CurrentMode = LitMode;
  vtkSmartPointer<vtkCamera> Camera;
  bool CameraPlaced = false;
  std::vector<vtkSmartPointer<vtkRenderer>> Renderers;
  std::vector<vtkSmartPointer<slSceneRenderer>> Panels;
  std::vector<vtkSmartPointer<slScene>> PanelScenes; ///< split mode: the scene at each frequency
  vtkSmartPointer<vtkPolyData> RenderedMesh;
  vtkSmartPointer<vtkPolyData> MeshWithNormals; ///< cache of meshWithNormals()
  vtkSmartPointer<vtkPolyData> FieldMesh;
  QString FieldName;
  std::string LastBrdfProblem; ///< the .brdf problem last reported, so that it is said once
  vtkSmartPointer<vtkPolyData> Lobe;
  bool ShowNormals = false;
  bool Picking = false;
  std::unique_ptr<LightWidgets> Widgets;
};

} // namespace viewer
} // namespace shadelab

#endif
