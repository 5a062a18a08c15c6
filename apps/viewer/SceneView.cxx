#include "SceneView.h"

#include "LightWidgets.h"
#include "ViewerDocument.h"

#include "slFieldImageRenderer.h"
#include "slLightingPass.h"
#include "slOffscreen.h"
#include "slRenderNormals.h"
#include "slScene.h"
#include "slSceneRenderer.h"
#include "slUpdateOrThrow.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellPicker.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkHedgeHog.h>
#include <vtkImageData.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>

namespace shadelab
{
namespace viewer
{

namespace
{
const ShadingFrequency kSplitFrequencies[3] = { ShadingFrequency::Flat, ShadingFrequency::Gouraud,
  ShadingFrequency::Phong };
const char* const kSplitLabels[3] = { "flat", "Gouraud", "Phong" };

double diagonalOf(vtkPolyData* mesh)
{
  double b[6];
  mesh->GetBounds(b);
  return std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
}

vtkSmartPointer<vtkTextActor> label(const char* text)
{
  auto actor = vtkSmartPointer<vtkTextActor>::New();
  actor->SetInput(text);
  actor->GetTextProperty()->SetFontSize(18);
  actor->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
  actor->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  actor->SetPosition(0.04, 0.04);
  return actor;
}

/// The renderer's first actor: the mesh (overlays and glyphs come after it).
vtkActor* meshActorOf(vtkRenderer* renderer)
{
  return vtkActor::SafeDownCast(renderer->GetActors()->GetItemAsObject(0));
}
} // namespace

SceneView::SceneView(ViewerDocument* document, QWidget* parent)
  : QVTKOpenGLNativeWidget(parent)
  , Document(document)
  , Camera(vtkSmartPointer<vtkCamera>::New())
  , Widgets(new LightWidgets(document))
{
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  window->SetMultiSamples(0); // as offscreen: the same scene gives the same pixels
  this->setRenderWindow(window);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  this->interactor()->SetInteractorStyle(style);
  this->interactor()->AddObserver(vtkCommand::LeftButtonPressEvent, this, &SceneView::onLeftButton, 10.0f);
  this->Camera->AddObserver(vtkCommand::ModifiedEvent, this, &SceneView::onCameraModified);

  connect(document, &ViewerDocument::meshChanged, this, [this] {
    this->RenderedMesh = nullptr;
    this->MeshWithNormals = nullptr;
    this->Lobe = nullptr;
    this->FieldMesh = nullptr;
    if (this->CurrentMode == FieldMode)
    {
      this->CurrentMode = LitMode;
    }
    this->rebuild(false);
  });
  // New normals or tangents: the same mesh, rebuilt in the same view.
  const auto remesh = [this] {
    this->MeshWithNormals = nullptr;
    this->RenderedMesh = nullptr;
    this->rebuild(true);
  };
  connect(document, &ViewerDocument::normalsChanged, this, remesh);
  connect(document, &ViewerDocument::tangentsChanged, this, remesh);
  connect(document, &ViewerDocument::sceneChanged, this, &SceneView::onSceneChanged);
  this->rebuild(false);
}

SceneView::~SceneView() = default;

void SceneView::setMode(Mode mode)
{
  if (mode == FieldMode && !this->FieldMesh)
  {
    this->report("no field computed yet: choose one in the fields panel");
    return;
  }
  const bool refit = (mode == SplitMode) != (this->CurrentMode == SplitMode);
  this->CurrentMode = mode;
  this->rebuild(true);
  if (refit && this->Document->mesh())
  {
    // Thirds of the window are narrower than the whole: fit the mesh again
    // (same direction), and again when going back to one panel.
    this->Renderers.front()->ResetCamera();
    this->renderNow();
  }
}

void SceneView::setField(vtkPolyData* mesh, const QString& arrayName)
{
  this->FieldMesh = mesh;
  this->FieldName = arrayName;
  this->CurrentMode = mesh ? FieldMode : LitMode;
  this->rebuild(true);
}

vtkPolyData* SceneView::fieldMesh() const
{
  return this->FieldMesh;
}

void SceneView::setNormalGlyphs(bool shown)
{
  this->ShowNormals = shown;
  this->rebuild(true);
}

void SceneView::setLightWidgets(bool shown)
{
  this->Widgets->setEnabled(shown);
  this->renderNow();
}

void SceneView::setLobe(vtkPolyData* lobe)
{
  this->Lobe = lobe;
  this->rebuild(true);
}

void SceneView::setPicking(bool on)
{
  this->Picking = on;
}

vtkCamera* SceneView::camera() const
{
  return this->Camera;
}

vtkPolyData* SceneView::meshWithNormals()
{
  if (!this->MeshWithNormals && this->RenderedMesh)
  {
    NormalsSettings settings = this->Document->normals();
    settings.replace = false; // the rendered mesh's normals are the ones to use
    try
    {
      this->MeshWithNormals = slWithRenderNormals(this->RenderedMesh, settings);
    }
    catch (const shadelab::Error& e)
    {
      this->report(QString::fromStdString(e.what()));
    }
  }
  return this->MeshWithNormals;
}

slLightingPass* SceneView::lightingPass(int i) const
{
  return i >= 0 && i < static_cast<int>(this->Panels.size()) ? this->Panels[static_cast<size_t>(i)]->GetLightingPass()
                                                              : nullptr;
}

void SceneView::renderNow()
{
  this->renderWindow()->Render();
  // A .brdf file's GLSL is compiled when its shaders are built, in Render().
  std::string brdfProblem;
  for (auto& panel : this->Panels)
  {
    brdfProblem = *panel->GetLightingPass()->GetBrdfError() ? panel->GetLightingPass()->GetBrdfError() : brdfProblem;
  }
  if (!brdfProblem.empty() && brdfProblem != this->LastBrdfProblem)
  {
    this->report(QString::fromStdString(brdfProblem));
  }
  this->LastBrdfProblem = brdfProblem;
}

vtkSmartPointer<vtkImageData> SceneView::grabImage()
{
  // The light widgets are handles, not part of the picture: the capture is
  // what `shadelab render` writes for the same scene.
  const bool widgets = this->Widgets->enabled();
  this->Widgets->setEnabled(false);
  vtkSmartPointer<vtkImageData> image = slCaptureWindow(this->renderWindow());
  this->Widgets->setEnabled(widgets);
  return image;
}

void SceneView::report(const QString& message)
{
  emit problem(message);
}

void SceneView::rebuild(bool keepCamera)
{
  this->Widgets->detach();
  vtkRenderWindow* window = this->renderWindow();
  for (auto& renderer : this->Renderers)
  {
    window->RemoveRenderer(renderer);
  }
  this->Renderers.clear();
  this->Panels.clear();
  this->PanelScenes.clear();
  if (!keepCamera)
  {
    this->CameraPlaced = false;
  }

  if (this->Document->mesh())
  {
    if (this->CurrentMode == FieldMode && this->FieldMesh)
    {
      this->buildFieldPanel();
    }
    else
    {
      this->buildLitPanels();
    }
  }
  if (this->Renderers.empty())
  {
    auto empty = vtkSmartPointer<vtkRenderer>::New();
    const glm::vec3& background = this->Document->scene().background;
    empty->SetBackground(background.x, background.y, background.z);
    this->Renderers.push_back(empty);
  }
  for (auto& renderer : this->Renderers)
  {
    window->AddRenderer(renderer);
    if (this->ShowNormals && this->RenderedMesh)
    {
      this->addNormalGlyphs(renderer);
    }
    renderer->ResetCameraClippingRange();
  }
  if (this->CurrentMode != SplitMode && this->RenderedMesh)
  {
    double bounds[6];
    this->RenderedMesh->GetBounds(bounds);
    this->Widgets->attach(this->interactor(), this->Renderers.front(), bounds);
  }
  this->renderNow();
}

void SceneView::buildLitPanels()
{
  const bool split = this->CurrentMode == SplitMode;
  const int count = split ? 3 : 1;
  const NormalsSettings& normals = this->Document->normals();
  for (int i = 0; i < count; ++i)
  {
    slScene* scene = this->Document->vtkScene();
    if (split)
    {
      auto atFrequency = vtkSmartPointer<slScene>::New();
      Scene copy = this->Document->scene();
      copy.frequency = kSplitFrequencies[i];
      atFrequency->SetScene(copy);
      this->PanelScenes.push_back(atFrequency);
      scene = atFrequency;
    }
    auto panel = vtkSmartPointer<slSceneRenderer>::New();
    panel->SetScene(scene);
    panel->SetMesh(this->Document->mesh());
    panel->SetNormalsWeighting(normals.weighting);
    panel->SetSplitting(normals.splitting);
    panel->SetFeatureAngle(normals.featureAngle);
    panel->SetReplaceNormals(normals.replace);
    // The camera is fitted for the panel's own aspect ratio.
    const qreal ratio = this->devicePixelRatioF();
    panel->SetWidth(std::max(1, static_cast<int>(this->width() * ratio / count)));
    panel->SetHeight(std::max(1, static_cast<int>(this->height() * ratio)));
    if (this->Lobe && !split)
    {
      panel->AddOverlay(this->Lobe, 1.0, 0.55, 0.1);
    }
    try
    {
      slCallOrThrow(panel, [&] { return panel->Prepare(); });
    }
    catch (const shadelab::Error& e)
    {
      this->report(QString::fromStdString(e.what()));
      this->Renderers.clear();
      this->Panels.clear();
      return;
    }
    vtkRenderer* renderer = panel->GetRenderer();
    renderer->SetViewport(static_cast<double>(i) / count, 0.0, static_cast<double>(i + 1) / count, 1.0);
    if (split)
    {
      renderer->AddActor2D(label(kSplitLabels[i]));
    }
    this->Panels.push_back(panel);
    this->Renderers.push_back(renderer);
  }
  // The Phong panel's mesh carries the normals (a flat panel needs none).
  if (this->RenderedMesh != this->Panels.back()->GetRenderedMesh())
  {
    this->RenderedMesh = this->Panels.back()->GetRenderedMesh();
    this->MeshWithNormals = nullptr;
  }
  if (!this->CameraPlaced)
  {
    this->Camera->DeepCopy(this->Renderers.front()->GetActiveCamera());
    this->CameraPlaced = true;
  }
  for (auto& renderer : this->Renderers)
  {
    renderer->SetActiveCamera(this->Camera);
  }
}

void SceneView::buildFieldPanel()
{
  const qreal ratio = this->devicePixelRatioF();
  vtkSmartPointer<vtkRenderer> renderer;
  try
  {
    renderer = slFieldImageRenderer::NewFieldRenderer(this->FieldMesh, this->FieldName.toStdString(),
      static_cast<int>(this->width() * ratio), static_cast<int>(this->height() * ratio));
  }
  catch (const shadelab::Error& e)
  {
    this->report(QString::fromStdString(e.what()));
    return;
  }
  const glm::vec3& background = this->Document->scene().background;
  renderer->SetBackground(background.x, background.y, background.z);
  if (!this->CameraPlaced)
  {
    this->Document->vtkScene()->ApplyCamera(renderer->GetActiveCamera(), this->FieldMesh->GetBounds(),
      static_cast<int>(this->width() * ratio), static_cast<int>(this->height() * ratio));
    renderer->ResetCameraClippingRange();
    this->Camera->DeepCopy(renderer->GetActiveCamera());
    this->CameraPlaced = true;
  }
  renderer->SetActiveCamera(this->Camera);
  this->Renderers.push_back(renderer);
}

void SceneView::addNormalGlyphs(vtkRenderer* renderer)
{
  vtkPolyData* withNormals = this->meshWithNormals();
  if (!withNormals)
  {
    return;
  }
  vtkNew<vtkHedgeHog> hedgehog;
  hedgehog->SetInputData(withNormals);
  hedgehog->SetVectorModeToUseNormal();
  hedgehog->SetScaleFactor(0.03 * diagonalOf(withNormals));
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(hedgehog->GetOutputPort());
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff(); // the pass leaves unlit actors to VTK
  actor->GetProperty()->SetColor(1.0, 0.85, 0.2);
  renderer->AddActor(actor);
}

void SceneView::onSceneChanged(int changes)
{
  if (changes & CameraChange)
  {
    this->rebuild(false); // a new scene: its camera replaces the view's
    return;
  }
  if ((changes & ShadingChange) && this->CurrentMode != FieldMode)
  {
    this->rebuild(true); // another frequency may need other normals
    return;
  }
  // In field mode the fields panel recomputes the field and calls setField().
  // Material, lights and background are uniforms and clear colours.
  const Scene& scene = this->Document->scene();
  for (size_t i = 0; i < this->Panels.size(); ++i)
  {
    slScene* panelScene = this->Document->vtkScene();
    if (i < this->PanelScenes.size())
    {
      Scene copy = scene;
      copy.frequency = kSplitFrequencies[i];
      this->PanelScenes[i]->SetScene(copy);
      panelScene = this->PanelScenes[i];
    }
    this->Panels[i]->GetLightingPass()->SetScene(panelScene);
  }
  for (auto& renderer : this->Renderers)
  {
    renderer->SetBackground(scene.background.x, scene.background.y, scene.background.z);
  }
  this->Widgets->sync();
  this->renderNow();
}

void SceneView::onCameraModified(vtkObject*, unsigned long, void*)
{
  this->Widgets->sync(); // camera lights move with the camera
}

bool SceneView::pickAt(int x, int y)
{
  if (!this->RenderedMesh || this->Renderers.empty())
  {
    return false;
  }
  vtkRenderer* renderer = this->Renderers.front();
  vtkNew<vtkCellPicker> picker;
  picker->SetTolerance(0.0005);
  picker->PickFromListOn();
  picker->AddPickList(meshActorOf(renderer));
  if (!picker->Pick(x, y, 0.0, renderer))
  {
    return false;
  }
  const double* p = picker->GetPickPosition();
  emit pointPicked(p[0], p[1], p[2]);
  return true;
}

bool SceneView::onLeftButton(vtkObject*, unsigned long, void*)
{
  if (!this->Picking)
  {
    return false;
  }
  const int* position = this->interactor()->GetEventPosition();
  this->pickAt(position[0], position[1]);
  return true; // consumed: no rotation while picking
}

} // namespace viewer
} // namespace shadelab
