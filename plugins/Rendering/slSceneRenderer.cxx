#include "slSceneRenderer.h"

#include "slCoreBoundary.h"
#include "slFiniteParameters.h"
#include "slLightingPass.h"
#include "slOffscreen.h"
#include "slRenderNormals.h"
#include "slScene.h"
#include "slUpdateOrThrow.h"

#include "shadelab/SceneLimits.h"

#include <vtkActor.h>
#include <vtkImageData.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <vtkAutoInit.h>
// The render window factory lives in RenderingOpenGL2; make sure it is registered.
VTK_MODULE_INIT(vtkRenderingOpenGL2);

#include "shadelab/Scene.h"

#include <algorithm>
#include <cstdlib>

vtkStandardNewMacro(slSceneRenderer);

slSceneRenderer::slSceneRenderer()
  : LightingPass(vtkSmartPointer<slLightingPass>::New())
{
}
slSceneRenderer::~slSceneRenderer() = default;

void slSceneRenderer::SetScene(slScene* scene)
{
  this->Scene = scene;
  this->Modified();
}
slScene* slSceneRenderer::GetScene()
{
  return this->Scene;
}
void slSceneRenderer::SetMesh(vtkPolyData* mesh)
{
  this->Mesh = mesh;
  this->Modified();
}
vtkPolyData* slSceneRenderer::GetMesh()
{
  return this->Mesh;
}
slLightingPass* slSceneRenderer::GetLightingPass()
{
  return this->LightingPass;
}

void slSceneRenderer::AddOverlay(vtkPolyData* overlay, double r, double g, double b)
{
  this->Overlays.push_back({ overlay, { r, g, b } });
  this->Modified();
}

void slSceneRenderer::RemoveAllOverlays()
{
  this->Overlays.clear();
  this->Modified();
}

vtkImageData* slSceneRenderer::GetImage()
{
  return this->Image;
}
vtkRenderer* slSceneRenderer::GetRenderer()
{
  return this->Renderer;
}
vtkRenderWindow* slSceneRenderer::GetRenderWindow()
{
  return this->Window;
}
vtkActor* slSceneRenderer::GetActor()
{
  return this->Actor;
}

bool slSceneRenderer::HasDisplay()
{
  return slDisplayProblem().empty();
}

vtkPolyData* slSceneRenderer::GetRenderedMesh()
{
  return this->RenderedMesh;
}

namespace
{
/// 0 (the scene's size) or @p size clamped to the scene format's range.
int imageSizeOrScenes(int size)
{
  return size <= 0 ? 0 : std::max(shadelab::kMinImageSize, std::min(size, shadelab::kMaxImageSize));
}
} // namespace

void slSceneRenderer::SetWidth(int width)
{
  width = imageSizeOrScenes(width);
  if (width != this->Width)
  {
    this->Width = width;
    this->Modified();
  }
}

void slSceneRenderer::SetHeight(int height)
{
  height = imageSizeOrScenes(height);
  if (height != this->Height)
  {
    this->Height = height;
    this->Modified();
  }
}

bool slSceneRenderer::Render()
{
  this->Image = nullptr;
  if (!this->Prepare())
  {
    return false;
  }
  const std::string displayProblem = slDisplayProblem();
  if (!displayProblem.empty())
  {
    vtkErrorMacro(<< displayProblem);
    return false;
  }
  const shadelab::Scene& scene = this->Scene->GetScene();
  this->Window = slOffscreenWindow(this->Width > 0 ? this->Width : scene.width, this->Height > 0 ? this->Height : scene.height);
  this->Window->AddRenderer(this->Renderer);
  // Its size is within the scene format's, which every OpenGL here draws;
  // a context that cannot be made throws (the caller names it).
  this->Image = slCaptureWindow(this->Window);
  // A .brdf file whose GLSL does not compile is known once its shaders are built.
  if (this->UseShadeLabLighting && *this->LightingPass->GetBrdfError())
  {
    vtkErrorMacro(<< this->LightingPass->GetBrdfError());
    this->Image = nullptr;
    return false;
  }
  return true;
}

bool slSceneRenderer::Prepare()
{
  this->RenderedMesh = nullptr;
  if (!this->Scene || !this->Mesh)
  {
    vtkErrorMacro(<< "slSceneRenderer needs a scene and a mesh");
    return false;
  }
  const std::string badParameter = slNonFiniteParameter({ { "FeatureAngle", this->FeatureAngle } });
  if (!badParameter.empty())
  {
    vtkErrorMacro(<< badParameter);
    return false;
  }
  const shadelab::Scene& scene = this->Scene->GetScene();

  vtkSmartPointer<vtkPolyData> mesh = this->Mesh;
  if (scene.frequency != shadelab::ShadingFrequency::Flat || this->ReplaceNormals)
  {
    slRenderNormalsOptions options;
    options.weighting = this->NormalsWeighting;
    options.splitting = this->Splitting;
    options.featureAngle = this->FeatureAngle;
    options.replace = this->ReplaceNormals;
    if (!slRunCore(this, [&] { mesh = slWithRenderNormals(this->Mesh, options); }))
    {
      return false;
    }
  }

  this->RenderedMesh = mesh;
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  mapper->ScalarVisibilityOff();
  this->Actor = vtkSmartPointer<vtkActor>::New();
  this->Actor->SetMapper(mapper);
  // The scene names the texture file it cannot read; this renderer reports it.
  if (!slRunCore(this, [&] { slCallOrThrow(this->Scene, [&] { return this->Scene->ApplyToActor(this->Actor); }); }))
  {
    return false;
  }

  this->Renderer = vtkSmartPointer<vtkRenderer>::New();
  this->Renderer->AddActor(this->Actor);
  for (const Overlay& overlay : this->Overlays)
  {
    // A uniform RGB point array: the lighting pass takes scalars as base colour.
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetNumberOfComponents(3);
    colours->SetNumberOfTuples(overlay.data->GetNumberOfPoints());
    for (int c = 0; c < 3; ++c)
    {
      colours->FillComponent(c, 255.0 * std::min(1.0, std::max(0.0, overlay.rgb[c])));
    }
    vtkNew<vtkPolyData> coloured;
    coloured->ShallowCopy(overlay.data);
    coloured->GetPointData()->SetScalars(colours);
    vtkNew<vtkPolyDataMapper> overlayMapper;
    overlayMapper->SetInputData(coloured);
    overlayMapper->SetColorModeToDirectScalars();
    overlayMapper->ScalarVisibilityOn();
    vtkNew<vtkActor> overlayActor;
    overlayActor->SetMapper(overlayMapper);
    this->Scene->ApplyMaterial(overlayActor->GetProperty());
    this->Renderer->AddActor(overlayActor);
  }
  // Fitted to the mesh alone (not the overlays), as the CPU filters fit it.
  this->Scene->ApplyToRenderer(this->Renderer, mesh->GetBounds(), this->Width, this->Height);
  if (this->UseShadeLabLighting)
  {
    // The pass reads the scene's model and frequency each time it is given the scene.
    this->LightingPass->SetScene(this->Scene);
    this->Renderer->SetPass(this->LightingPass);
    if (*this->LightingPass->GetBrdfError())
    {
      vtkErrorMacro(<< this->LightingPass->GetBrdfError());
      return false;
    }
  }
  return true;
}

void slSceneRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UseShadeLabLighting: " << this->UseShadeLabLighting << "\n";
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "NormalsWeighting: " << this->NormalsWeighting << "\n";
  os << indent << "Splitting: " << this->Splitting << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "ReplaceNormals: " << this->ReplaceNormals << "\n";
  os << indent << "Scene: " << (this->Scene ? "set" : "(none)") << "\n";
  os << indent << "Mesh: " << (this->Mesh ? "set" : "(none)") << "\n";
}
