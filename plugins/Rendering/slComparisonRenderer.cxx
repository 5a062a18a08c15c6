#include "slComparisonRenderer.h"

#include "slCoreBoundary.h"
#include "slLightingPass.h"
#include "slRenderNormals.h"
#include "slScene.h"
#include "slOffscreen.h"
#include "slUpdateOrThrow.h"

#include "shadelab/Scene.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <vtkAutoInit.h>
VTK_MODULE_INIT(vtkRenderingFreeType); // labels and scalar bars draw text

#include <algorithm>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(slComparisonRenderer);

namespace
{
vtkSmartPointer<vtkTextActor> label(const std::string& text, int panelHeight)
{
  auto actor = vtkSmartPointer<vtkTextActor>::New();
  actor->SetInput(text.c_str());
  vtkTextProperty* p = actor->GetTextProperty();
  p->SetFontSize(std::max(12, panelHeight / 16));
  p->SetColor(1.0, 1.0, 1.0);
  p->SetJustificationToCentered();
  p->SetVerticalJustificationToTop();
  actor->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  actor->SetPosition(0.5, 0.97);
  return actor;
}
} // namespace

slComparisonRenderer::slComparisonRenderer() = default;
slComparisonRenderer::~slComparisonRenderer() = default;

void slComparisonRenderer::SetScene(slScene* scene)
{
  this->Scene = scene;
  this->Modified();
}

void slComparisonRenderer::SetMesh(vtkPolyData* mesh)
{
  this->Mesh = mesh;
  this->Modified();
}

bool slComparisonRenderer::AddPanel(const char* text, const char* model, const char* frequency)
{
  shadelab::ShadingModel m;
  shadelab::ShadingFrequency f;
  if (!model || !shadelab::parseModelName(model, m))
  {
    vtkErrorMacro(<< "AddPanel: " << shadelab::modelNameProblem(model));
    return false;
  }
  if (!frequency || !shadelab::parseFrequencyName(frequency, f))
  {
    vtkErrorMacro(<< "AddPanel: " << shadelab::frequencyNameProblem(frequency));
    return false;
  }
  this->Panels.push_back({ text ? text : "", static_cast<int>(m), static_cast<int>(f) });
  this->Modified();
  return true;
}

void slComparisonRenderer::RemoveAllPanels()
{
  this->Panels.clear();
  this->Modified();
}

void slComparisonRenderer::SetDifference(int a, int b, double amplification)
{
  this->DifferenceA = a;
  this->DifferenceB = b;
  this->Amplification = amplification;
  this->Modified();
}

bool slComparisonRenderer::Render()
{
  const int n = static_cast<int>(this->Panels.size());
  const bool difference = this->DifferenceA >= 0;
  if (!this->Scene || !this->Mesh || n == 0)
  {
    vtkErrorMacro(<< "slComparisonRenderer needs a scene, a mesh and at least one panel");
    return false;
  }
  if (difference && (this->DifferenceA >= n || this->DifferenceB < 0 || this->DifferenceB >= n))
  {
    vtkErrorMacro(<< "difference panels " << this->DifferenceA << " and " << this->DifferenceB << " do not exist");
    return false;
  }
  const int cells = n + (difference ? 1 : 0);
  int width = 0, height = 0;
  this->GetCompositeSize(cells, width, height);
  const std::string sizeProblem = slWindowSizeProblem(width, height);
  if (!sizeProblem.empty())
  {
    vtkErrorMacro(<< cells << " panels of " << this->PanelWidth << "x" << this->PanelHeight << ": " << sizeProblem);
    return false;
  }
  const std::string displayProblem = slDisplayProblem();
  if (!displayProblem.empty())
  {
    vtkErrorMacro(<< displayProblem);
    return false;
  }

  vtkSmartPointer<vtkPolyData> mesh;
  if (!slRunCore(this, [&] { mesh = slWithRenderNormals(this->Mesh); }))
  {
    return false;
  }

  vtkSmartPointer<vtkRenderWindow> window = slOffscreenWindow(width, height);
  // A window-wide renderer, drawn first, gives the cells no panel covers
  // the scene's background.
  vtkNew<vtkRenderer> backdrop;
  const glm::vec3 background = this->Scene->GetScene().background;
  backdrop->SetBackground(background.x, background.y, background.z);
  window->AddRenderer(backdrop);
  auto viewport = [&](vtkRenderer* renderer, int index) {
    int x = 0, y = 0;
    this->cellOrigin(index, cells, x, y);
    renderer->SetViewport(static_cast<double>(x) / width, static_cast<double>(y) / height,
      static_cast<double>(x + this->PanelWidth) / width, static_cast<double>(y + this->PanelHeight) / height);
  };
  vtkNew<vtkCamera> camera; // linked: every panel shows this one camera
  std::vector<vtkSmartPointer<vtkTextActor>> labels;

  for (int i = 0; i < n; ++i)
  {
    const Panel& panel = this->Panels[static_cast<size_t>(i)];
    vtkNew<vtkPolyDataMapper> mapper; // one mapper per panel: each keeps its own shaders
    mapper->SetInputData(mesh);
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    // The scene names the texture file it cannot read; this renderer reports it.
    if (!slRunCore(this, [&] { slCallOrThrow(this->Scene, [&] { return this->Scene->ApplyToActor(actor); }); }))
    {
      return false;
    }
    vtkNew<vtkRenderer> renderer;
    viewport(renderer, i);
    renderer->SetActiveCamera(camera);
    renderer->AddActor(actor);
    labels.push_back(label(panel.label, this->PanelHeight));
    renderer->AddActor2D(labels.back());
    this->Scene->ApplyToRenderer(renderer, mesh->GetBounds(), this->PanelWidth, this->PanelHeight);
    vtkNew<slLightingPass> pass;
    pass->SetScene(this->Scene);
    pass->SetModel(panel.model);
    pass->SetFrequency(panel.frequency);
    renderer->SetPass(pass);
    window->AddRenderer(renderer);
  }
  if (difference)
  {
    vtkNew<vtkRenderer> renderer;
    viewport(renderer, n);
    renderer->SetBackground(0.0, 0.0, 0.0);
    std::ostringstream text;
    text << "|" << this->Panels[static_cast<size_t>(this->DifferenceA)].label << " - "
         << this->Panels[static_cast<size_t>(this->DifferenceB)].label << "| x " << this->Amplification;
    labels.push_back(label(text.str(), this->PanelHeight));
    renderer->AddActor2D(labels.back());
    window->AddRenderer(renderer);
  }

  // Once without labels (the difference must not see them), once with.
  auto capture = [&window](bool withLabels, std::vector<vtkSmartPointer<vtkTextActor>>& texts) {
    for (auto& t : texts)
    {
      t->SetVisibility(withLabels);
    }
    return slCaptureWindow(window);
  };
  // A capture that finds nothing drawn throws: one line, as every failure here.
  vtkSmartPointer<vtkImageData> plain;
  vtkSmartPointer<vtkImageData> image;
  if (!slRunCore(this, [&] {
        plain = difference ? capture(false, labels) : nullptr;
        image = capture(true, labels);
      }))
  {
    return false;
  }
  this->Image = image;
  if (difference)
  {
    this->FillDifference(plain, this->Image);
  }
  return true;
}

void slComparisonRenderer::GetCompositeSize(int cells, int& width, int& height) const
{
  cells = std::max(cells, 1);
  const int columns = this->columns(cells);
  const int rows = (cells + columns - 1) / columns;
  width = columns * this->PanelWidth;
  height = rows * this->PanelHeight;
}

int slComparisonRenderer::columns(int cells) const
{
  return this->Columns > 0 ? std::min(this->Columns, cells) : cells;
}

void slComparisonRenderer::cellOrigin(int index, int cells, int& x, int& y) const
{
  const int columns = this->columns(cells);
  const int rows = (cells + columns - 1) / columns;
  x = (index % columns) * this->PanelWidth;
  y = (rows - 1 - index / columns) * this->PanelHeight; // the first row on top
}

void slComparisonRenderer::FillDifference(vtkImageData* plain, vtkImageData* image) const
{
  // The difference panel so far holds only its label (white on black); the
  // amplified difference of the unlabelled panels goes underneath it.
  auto* source = vtkUnsignedCharArray::SafeDownCast(plain->GetPointData()->GetScalars());
  auto* pixels = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  int dims[3];
  image->GetDimensions(dims);
  const int n = static_cast<int>(this->Panels.size());
  int targetX = 0, targetY = 0, aX = 0, aY = 0, bX = 0, bY = 0;
  this->cellOrigin(n, n + 1, targetX, targetY);
  this->cellOrigin(this->DifferenceA, n + 1, aX, aY);
  this->cellOrigin(this->DifferenceB, n + 1, bX, bY);
  auto at = [&dims](int x, int y) { return 3 * (static_cast<vtkIdType>(y) * dims[0] + x); };
  for (int y = 0; y < this->PanelHeight; ++y)
  {
    for (int x = 0; x < this->PanelWidth; ++x)
    {
      const vtkIdType target = at(targetX + x, targetY + y);
      const vtkIdType a = at(aX + x, aY + y);
      const vtkIdType b = at(bX + x, bY + y);
      for (int c = 0; c < 3; ++c)
      {
        const double d = std::abs(source->GetValue(a + c) - source->GetValue(b + c)) * this->Amplification;
        const unsigned char labelValue = pixels->GetValue(target + c);
        pixels->SetValue(target + c, std::max(labelValue, static_cast<unsigned char>(std::min(255.0, d))));
      }
    }
  }
}

void slComparisonRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Panels: " << this->Panels.size() << "\n";
  for (const Panel& p : this->Panels)
  {
    os << indent << "  " << p.label << ": " << shadelab::modelName(static_cast<shadelab::ShadingModel>(p.model))
       << ", " << shadelab::frequencyName(static_cast<shadelab::ShadingFrequency>(p.frequency)) << "\n";
  }
  os << indent << "Columns: " << this->Columns << "\n";
  os << indent << "Difference: " << this->DifferenceA << " - " << this->DifferenceB << " x " << this->Amplification
     << "\n";
}
