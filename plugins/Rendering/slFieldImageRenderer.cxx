#include "slFieldImageRenderer.h"

#include "shadelab/LightingGLSL.h"

#include "slCoreBoundary.h"
#include "slScene.h"
#include "slOffscreen.h"
#include "slUpdateOrThrow.h"

#include "shadelab/Scene.h"

#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSphereSource.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTransform.h>

#include <vtkAutoInit.h>
VTK_MODULE_INIT(vtkRenderingFreeType); // labels and scalar bars draw text

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(slFieldImageRenderer);

namespace
{
/// The values to map: the array itself (1 component) or its luminance (RGB).
vtkSmartPointer<vtkFloatArray> scalarsOf(vtkDataArray* array)
{
  auto out = vtkSmartPointer<vtkFloatArray>::New();
  out->SetName(array->GetName());
  out->SetNumberOfTuples(array->GetNumberOfTuples());
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    const double v = array->GetNumberOfComponents() >= 3
      ? shadelab::glsl::slLuminance(glm::vec3(array->GetComponent(i, 0), array->GetComponent(i, 1), array->GetComponent(i, 2)))
      : array->GetComponent(i, 0);
    out->SetValue(i, static_cast<float>(std::isfinite(v) ? v : 0.0));
  }
  return out;
}

/// slDiverging (blue-white-red), symmetric about 0, when the range straddles
/// 0; otherwise slRamp (dark blue to yellow) over the range.
vtkSmartPointer<vtkLookupTable> lookupTableFor(double range[2])
{
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(256);
  const bool diverging = range[0] < 0.0 && range[1] > 0.0;
  if (diverging)
  {
    const double m = std::max(-range[0], range[1]);
    range[0] = -m;
    range[1] = m;
  }
  if (!(range[1] > range[0]))
  {
    // A constant field: centre it in a narrow range, so the bar reads its value.
    const double pad = std::max(1e-6, 0.05 * std::abs(range[0]));
    range[0] -= pad;
    range[1] += pad;
  }
  table->SetTableRange(range);
  for (int i = 0; i < 256; ++i)
  {
    const double s = i / 255.0;
    // The component views' ramps (slFalseColor.glsl), sampled into the table.
    const glm::vec3 c = diverging ? shadelab::glsl::slDiverging(static_cast<float>(2.0 * s - 1.0))
                                  : shadelab::glsl::slRamp(static_cast<float>(s));
    const double rgb[3] = { c.x, c.y, c.z };
    table->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0);
  }
  table->Build();
  return table;
}

vtkSmartPointer<vtkActor> glyphActor(vtkAlgorithmOutput* source, const glm::vec3& colour)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour.x, colour.y, colour.z);
  actor->GetProperty()->LightingOff();
  return actor;
}

/// Glyphs for the scene's lights, in world space for @p camera.
std::vector<vtkSmartPointer<vtkActor>> lightGlyphs(const shadelab::Scene& scene, vtkCamera* camera, const double bounds[6])
{
  // bounds is (xmin, xmax, ymin, ymax, zmin, zmax).
  const double lo[3] = { bounds[0], bounds[2], bounds[4] }, hi[3] = { bounds[1], bounds[3], bounds[5] };
  const double size = std::sqrt(vtkMath::Distance2BetweenPoints(lo, hi));
  const glm::vec3 centre(0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2]));
  const glm::vec3 eye(camera->GetPosition()[0], camera->GetPosition()[1], camera->GetPosition()[2]);
  const glm::vec3 focal(camera->GetFocalPoint()[0], camera->GetFocalPoint()[1], camera->GetFocalPoint()[2]);
  const glm::vec3 up(camera->GetViewUp()[0], camera->GetViewUp()[1], camera->GetViewUp()[2]);
  std::vector<vtkSmartPointer<vtkActor>> actors;
  for (const shadelab::SceneLight& sceneLight : scene.lights)
  {
    if (!shadelab::lightHasDirection(static_cast<int>(sceneLight.type)))
    {
      continue;
    }
    const shadelab::SceneLight l = shadelab::lightInWorldSpace(sceneLight, eye, focal, up);
    const glm::vec3 colour = glm::min(glm::vec3(1.0f), glm::max(glm::vec3(0.15f), l.diffuse));
    if (!shadelab::lightTakes(l.type, shadelab::kLightPosition))
    {
      // An arrow outside the mesh, pointing along the light toward its centre.
      const glm::vec3 d = glm::normalize(l.direction);
      const glm::vec3 start = centre - d * static_cast<float>(0.9 * size);
      vtkNew<vtkArrowSource> arrow;
      vtkNew<vtkTransform> placement;
      placement->Translate(start.x, start.y, start.z);
      const glm::vec3 axis = glm::cross(glm::vec3(1.0f, 0.0f, 0.0f), d);
      const double angle = vtkMath::DegreesFromRadians(std::acos(std::max(-1.0f, std::min(1.0f, d.x))));
      if (glm::length(axis) > 1e-6f)
      {
        placement->RotateWXYZ(angle, axis.x, axis.y, axis.z);
      }
      else if (d.x < 0.0f)
      {
        placement->RotateWXYZ(180.0, 0.0, 1.0, 0.0);
      }
      placement->Scale(0.3 * size, 0.3 * size, 0.3 * size);
      auto actor = glyphActor(arrow->GetOutputPort(), colour);
      actor->SetUserTransform(placement);
      actors.push_back(actor);
    }
    else
    {
      vtkNew<vtkSphereSource> sphere;
      sphere->SetCenter(l.position.x, l.position.y, l.position.z);
      sphere->SetRadius(0.03 * size);
      actors.push_back(glyphActor(sphere->GetOutputPort(), colour));
    }
  }
  return actors;
}
} // namespace

slFieldImageRenderer::slFieldImageRenderer() = default;
slFieldImageRenderer::~slFieldImageRenderer() = default;

void slFieldImageRenderer::SetMesh(vtkPolyData* mesh)
{
  this->Mesh = mesh;
  this->Modified();
}

void slFieldImageRenderer::SetScene(slScene* scene)
{
  this->Scene = scene;
  this->Modified();
}

void slFieldImageRenderer::AddField(const char* arrayName)
{
  this->Fields.emplace_back(arrayName ? arrayName : "");
  this->Modified();
}

void slFieldImageRenderer::RemoveAllFields()
{
  this->Fields.clear();
  this->Modified();
}

vtkSmartPointer<vtkRenderer> slFieldImageRenderer::NewFieldRenderer(
  vtkPolyData* mesh, const std::string& name, int panelWidth, int panelHeight)
{
  vtkDataArray* array = mesh->GetPointData()->GetArray(name.c_str());
  const bool cellArray = !array;
  if (!array)
  {
    array = mesh->GetCellData()->GetArray(name.c_str());
  }
  if (!array)
  {
    throw shadelab::Error("the mesh has no point or cell array \"" + name + "\"");
  }
  vtkSmartPointer<vtkFloatArray> values = scalarsOf(array);
  vtkNew<vtkPolyData> shown;
  shown->ShallowCopy(mesh);
  if (cellArray)
  {
    shown->GetCellData()->SetScalars(values);
  }
  else
  {
    shown->GetPointData()->SetScalars(values);
  }
  double range[2];
  values->GetRange(range);
  vtkSmartPointer<vtkLookupTable> table = lookupTableFor(range);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(shown);
  mapper->SetLookupTable(table);
  mapper->UseLookupTableScalarRangeOn();
  mapper->ScalarVisibilityOn();
  if (cellArray)
  {
    mapper->SetScalarModeToUseCellData();
  }
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff(); // the colours are the values

  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(table);
  bar->SetNumberOfLabels(5);
  bar->SetMaximumWidthInPixels(panelWidth / 6);
  bar->SetUnconstrainedFontSize(true);
  bar->GetLabelTextProperty()->SetFontSize(std::max(9, panelHeight / 28));
  bar->SetPosition(0.84, 0.08);
  bar->SetPosition2(0.15, 0.84);

  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->AddActor(actor);
  renderer->AddActor2D(bar);
  vtkNew<vtkTextActor> title;
  title->SetInput((name + (array->GetNumberOfComponents() >= 3 ? " (luminance)" : "")).c_str());
  title->GetTextProperty()->SetFontSize(std::max(12, panelHeight / 18));
  title->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
  title->GetTextProperty()->SetVerticalJustificationToBottom();
  title->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  title->SetPosition(0.03, 0.03);
  renderer->AddActor2D(title);
  return renderer;
}

bool slFieldImageRenderer::Render()
{
  if (!this->Mesh || !this->Scene || this->Fields.empty())
  {
    vtkErrorMacro(<< "slFieldImageRenderer needs a mesh, a scene and at least one field");
    return false;
  }
  const std::string displayProblem = slDisplayProblem();
  if (!displayProblem.empty())
  {
    vtkErrorMacro(<< displayProblem);
    return false;
  }
  const int n = static_cast<int>(this->Fields.size());
  const int columns = std::min(this->Columns, n);
  const int rows = (n + columns - 1) / columns;
  vtkSmartPointer<vtkRenderWindow> window = slOffscreenWindow(columns * this->PanelWidth, rows * this->PanelHeight);
  vtkNew<vtkCamera> camera;
  std::vector<vtkSmartPointer<vtkRenderer>> renderers;
  std::vector<vtkSmartPointer<vtkRenderer>> fillers;

  for (int i = 0; i < n; ++i)
  {
    vtkSmartPointer<vtkRenderer> renderer;
    if (!slRunCore(this, [&] {
          renderer = NewFieldRenderer(this->Mesh, this->Fields[static_cast<size_t>(i)], this->PanelWidth, this->PanelHeight);
        }))
    {
      return false;
    }
    const int row = i / columns, column = i % columns;
    renderer->SetViewport(static_cast<double>(column) / columns, 1.0 - static_cast<double>(row + 1) / rows,
      static_cast<double>(column + 1) / columns, 1.0 - static_cast<double>(row) / rows);
    renderer->SetActiveCamera(camera);
    window->AddRenderer(renderer);
    renderers.push_back(renderer);
  }
  for (int i = n; i < rows * columns; ++i) // empty cells of the last row
  {
    auto filler = vtkSmartPointer<vtkRenderer>::New();
    const int row = i / columns, column = i % columns;
    filler->SetViewport(static_cast<double>(column) / columns, 1.0 - static_cast<double>(row + 1) / rows,
      static_cast<double>(column + 1) / columns, 1.0 - static_cast<double>(row) / rows);
    window->AddRenderer(filler);
    fillers.push_back(filler);
  }
  // Place the shared camera on the mesh (the scene's camera or a fit), then
  // add the light glyphs, which need the final camera for camera lights.
  double bounds[6];
  this->Mesh->GetBounds(bounds);
  this->Scene->ApplyToRenderer(renderers.front(), bounds, this->PanelWidth, this->PanelHeight);
  for (auto& renderer : renderers)
  {
    renderer->SetBackground(renderers.front()->GetBackground());
    for (auto& glyph : lightGlyphs(this->Scene->GetScene(), camera, bounds))
    {
      renderer->AddActor(glyph);
    }
    renderer->ResetCameraClippingRange();
  }
  for (auto& filler : fillers)
  {
    filler->SetBackground(renderers.front()->GetBackground());
  }
  // A window that cannot be drawn is an error, not a black image.
  return slRunCore(this, [&] { this->Image = slCaptureWindow(window); });
}

void slFieldImageRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Fields:";
  for (const std::string& f : this->Fields)
  {
    os << " " << f;
  }
  os << "\n" << indent << "Columns: " << this->Columns << "\n";
}
