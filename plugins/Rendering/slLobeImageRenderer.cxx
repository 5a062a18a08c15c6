#include "slLobeImageRenderer.h"

#include "slAlbedoTable.h"
#include "slBRDFLobeSource.h"
#include "slCoreBoundary.h"
#include "slOffscreen.h"
#include "slUpdateOrThrow.h"

#include "shadelab/Scene.h"

#include <vtkActor.h>
#include <vtkAxis.h>
#include <vtkCamera.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextActor.h>
#include <vtkContextScene.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLineSource.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPlot.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include <vtkAutoInit.h>
// Charts draw through the OpenGL context device; text through FreeType.
VTK_MODULE_INIT(vtkRenderingContextOpenGL2);
VTK_MODULE_INIT(vtkRenderingFreeType);

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(slLobeImageRenderer);

namespace
{
/// Distinct colours (0-255) for up to six overlaid models.
const unsigned char kPalette[6][3] = { { 228, 26, 28 }, { 55, 126, 184 }, { 77, 175, 74 }, { 152, 78, 163 },
  { 255, 127, 0 }, { 166, 86, 40 } };

vtkSmartPointer<vtkActor> lineActor(const double from[3], const double to[3], double r, double g, double b)
{
  vtkNew<vtkLineSource> line;
  line->SetPoint1(from);
  line->SetPoint2(to);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(line->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  actor->GetProperty()->SetLineWidth(2.0);
  actor->GetProperty()->LightingOff();
  return actor;
}

vtkSmartPointer<vtkChartXY> makeChart(const char* title, const char* xTitle, const char* yTitle)
{
  auto chart = vtkSmartPointer<vtkChartXY>::New();
  chart->SetTitle(title);
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(xTitle);
  chart->GetAxis(vtkAxis::LEFT)->SetTitle(yTitle);
  chart->SetShowLegend(true);
  return chart;
}

/// Adds the chart as a viewport of @p window.
void addChartPanel(vtkRenderWindow* window, vtkChartXY* chart, double x0, double x1)
{
  vtkNew<vtkContextScene> scene;
  scene->AddItem(chart);
  vtkNew<vtkContextActor> actor;
  actor->SetScene(scene);
  vtkNew<vtkRenderer> renderer;
  renderer->SetViewport(x0, 0.0, x1, 1.0);
  renderer->SetBackground(1.0, 1.0, 1.0);
  renderer->AddActor(actor);
  scene->SetRenderer(renderer);
  window->AddRenderer(renderer);
}
} // namespace

slLobeImageRenderer::slLobeImageRenderer()
  : LobeParameters(vtkSmartPointer<slBRDFLobeSource>::New())
{
  this->PanelHeight = 360;
}

slBRDFLobeSource* slLobeImageRenderer::GetLobeParameters()
{
  return this->LobeParameters;
}
slLobeImageRenderer::~slLobeImageRenderer() = default;

bool slLobeImageRenderer::AddModel(const char* name)
{
  shadelab::ShadingModel model;
  if (!name || !shadelab::parseModelName(name, model) || this->Models.size() >= 6)
  {
    return false;
  }
  this->Models.push_back(static_cast<int>(model));
  this->Modified();
  return true;
}

void slLobeImageRenderer::RemoveAllModels()
{
  this->Models.clear();
  this->Modified();
}

bool slLobeImageRenderer::Render()
{
  if (this->Models.empty())
  {
    vtkErrorMacro(<< "slLobeImageRenderer needs at least one model");
    return false;
  }
  const std::string displayProblem = slDisplayProblem();
  if (!displayProblem.empty())
  {
    vtkErrorMacro(<< displayProblem);
    return false;
  }
  vtkSmartPointer<vtkRenderWindow> window = slOffscreenWindow(3 * this->PanelWidth, this->PanelHeight);

  vtkNew<vtkRenderer> lobes;
  lobes->SetViewport(0.0, 0.0, 1.0 / 3.0, 1.0);
  lobes->SetBackground(0.1, 0.1, 0.12);
  vtkSmartPointer<vtkChartXY> polar =
    makeChart("plane of incidence (polar)", "x  (along the surface)", "z  (normal)");
  vtkSmartPointer<vtkChartXY> albedo =
    makeChart("directional albedo", "incidence (degrees)", "albedo");

  vtkNew<slAlbedoTable> albedoTable;
  albedoTable->SetShininess(this->LobeParameters->GetShininess());
  albedoTable->Update();
  vtkTable* curves = albedoTable->GetOutput();

  double extent = 0.0;
  for (size_t i = 0; i < this->Models.size(); ++i)
  {
    const unsigned char* rgb = kPalette[i];
    const char* name = shadelab::modelName(static_cast<shadelab::ShadingModel>(this->Models[i]));
    vtkNew<slBRDFLobeSource> lobe;
    lobe->SetModel(this->Models[i]);
    slBRDFLobeSource* p = this->LobeParameters;
    lobe->SetShininess(p->GetShininess());
    lobe->SetIncidenceAngle(p->GetIncidenceAngle());
    lobe->SetDiffuseWeight(p->GetDiffuseWeight());
    lobe->SetSpecularWeight(p->GetSpecularWeight());
    lobe->SetMultiplyByCosine(p->GetMultiplyByCosine());
    lobe->Update();

    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(lobe->GetOutputPort(0));
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0);
    actor->GetProperty()->SetOpacity(this->Models.size() > 1 ? 0.55 : 1.0);
    lobes->AddActor(actor);
    const double* b = lobe->GetOutput(0)->GetBounds();
    extent = std::max({ extent, std::abs(b[0]), std::abs(b[1]), std::abs(b[5]) });

    // Polar slice: the slice's points in the x-z plane.
    vtkPolyData* slice = lobe->GetSliceOutput();
    vtkNew<vtkTable> table;
    vtkNew<vtkFloatArray> xs, zs;
    xs->SetName("x");
    zs->SetName(name);
    for (vtkIdType p = 0; p < slice->GetNumberOfPoints(); ++p)
    {
      double point[3];
      slice->GetPoint(p, point);
      xs->InsertNextValue(static_cast<float>(point[0]));
      zs->InsertNextValue(static_cast<float>(point[2]));
    }
    table->AddColumn(xs);
    table->AddColumn(zs);
    vtkPlot* line = polar->AddPlot(vtkChart::LINE);
    line->SetInputData(table, 0, 1);
    line->SetColor(rgb[0], rgb[1], rgb[2], 255);
    line->SetWidth(2.0);

    vtkPlot* curve = albedo->AddPlot(vtkChart::LINE);
    curve->SetInputData(curves, "IncidenceDegrees", name);
    curve->SetColor(rgb[0], rgb[1], rgb[2], 255);
    curve->SetWidth(2.0);
  }

  // Incident direction (toward the light) and mirror direction.
  const double t = this->LobeParameters->GetIncidenceAngle() * M_PI / 180.0;
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double light[3] = { -std::sin(t) * 1.2 * extent, 0.0, std::cos(t) * 1.2 * extent };
  const double mirror[3] = { std::sin(t) * 1.2 * extent, 0.0, std::cos(t) * 1.2 * extent };
  const double normal[3] = { 0.0, 0.0, 1.2 * extent };
  lobes->AddActor(lineActor(origin, light, 1.0, 0.9, 0.2));
  lobes->AddActor(lineActor(origin, mirror, 0.6, 0.6, 0.6));
  lobes->AddActor(lineActor(origin, normal, 0.9, 0.9, 0.9));
  vtkCamera* camera = lobes->GetActiveCamera();
  camera->SetPosition(0.0, -1.0, 0.35);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  lobes->ResetCamera();
  window->AddRenderer(lobes);
  addChartPanel(window, polar, 1.0 / 3.0, 2.0 / 3.0);
  addChartPanel(window, albedo, 2.0 / 3.0, 1.0);
  this->Image = slCaptureWindow(window);
  return true;
}

void slLobeImageRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Models:";
  for (int m : this->Models)
  {
    os << " " << shadelab::modelName(static_cast<shadelab::ShadingModel>(m));
  }
  os << "\n" << indent << "LobeParameters:\n";
  this->LobeParameters->PrintSelf(os, indent.GetNextIndent());
}
