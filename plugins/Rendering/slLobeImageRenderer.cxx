#include "slLobeImageRenderer.h"

#include "slAlbedoTable.h"
#include "slBRDFFileEvaluator.h"
#include "slBRDFLobeSource.h"
#include "slCoreBoundary.h"
#include "slMaterialNumbers.h"
#include "slOffscreen.h"
#include "slUpdateOrThrow.h"

#include "shadelab/Scene.h"

#include <vtkAbstractArray.h>
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
#include <memory>

vtkStandardNewMacro(slLobeImageRenderer);

namespace
{
/// Distinct colours (0-255) for up to six overlaid models.
const unsigned char kPalette[6][3] = { { 228, 26, 28 }, { 55, 126, 184 }, { 77, 175, 74 }, { 152, 78, 163 },
  { 255, 127, 0 }, { 166, 86, 40 } };
/// BRDFs overlaid at most: one colour each.
constexpr size_t kMaxEntries = sizeof(kPalette) / sizeof(kPalette[0]);

/// Incidence angles of the albedo curves, 0 to 89 degrees.
constexpr int kAlbedoCurveAngles = 46;

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
  if (!name || !shadelab::parseModelName(name, model))
  {
    vtkErrorMacro(<< "AddModel: " << shadelab::modelNameProblem(name));
    return false;
  }
  if (!this->HasRoomFor("AddModel"))
  {
    return false;
  }
  Entry entry;
  entry.Model = static_cast<int>(model);
  this->Entries.push_back(entry);
  this->Modified();
  return true;
}

bool slLobeImageRenderer::AddBRDFFile(const char* path)
{
  if (!path || !*path)
  {
    vtkErrorMacro(<< "AddBRDFFile: no file name given");
    return false;
  }
  if (!this->HasRoomFor("AddBRDFFile"))
  {
    return false;
  }
  Entry entry;
  entry.Path = path;
  this->Entries.push_back(entry);
  this->Modified();
  return true;
}

bool slLobeImageRenderer::HasRoomFor(const char* adder)
{
  if (this->Entries.size() < kMaxEntries)
  {
    return true;
  }
  vtkErrorMacro(<< adder << ": " << kMaxEntries << " BRDFs (models and .brdf files) are overlaid already, the most there can be");
  return false;
}

void slLobeImageRenderer::AddBRDFFileParameter(const char* nameValue)
{
  if (nameValue && !this->Entries.empty() && this->Entries.back().Model < 0)
  {
    this->Entries.back().Overrides.emplace_back(nameValue);
    this->Modified();
  }
}

void slLobeImageRenderer::GetColor(int index, unsigned char rgb[3])
{
  const unsigned char* c = kPalette[std::clamp(index, 0, static_cast<int>(kMaxEntries) - 1)];
  std::copy(c, c + 3, rgb);
}

void slLobeImageRenderer::RemoveAllModels()
{
  this->Entries.clear();
  this->Modified();
}

int slLobeImageRenderer::GetNumberOfBRDFFiles()
{
  return static_cast<int>(this->FileAlbedos.size());
}

double slLobeImageRenderer::GetBRDFFileAlbedo(int index)
{
  return index >= 0 && index < this->GetNumberOfBRDFFiles() ? this->FileAlbedos[static_cast<size_t>(index)] : 0.0;
}

std::string slLobeImageRenderer::GetBRDFFileName(int index)
{
  int file = 0;
  for (const Entry& entry : this->Entries)
  {
    if (entry.Model < 0 && file++ == index)
    {
      return shadelab::brdfDisplayName(entry.Path);
    }
  }
  return std::string();
}

bool slLobeImageRenderer::Render()
{
  if (this->Entries.empty())
  {
    vtkErrorMacro(<< "slLobeImageRenderer needs at least one model or .brdf file");
    return false;
  }
  const std::string displayProblem = slDisplayProblem();
  if (!displayProblem.empty())
  {
    vtkErrorMacro(<< displayProblem);
    return false;
  }
  // The .brdf files first: a file that cannot be read or compiled stops
  // here, before anything is drawn.
  std::vector<std::unique_ptr<slBRDFFileEvaluator>> evaluators;
  const bool filesReady = slRunCore(this, [&] {
    for (const Entry& entry : this->Entries)
    {
      if (entry.Model < 0)
      {
        const shadelab::BrdfFile file = shadelab::readBrdfFile(entry.Path);
        evaluators.emplace_back(
          new slBRDFFileEvaluator(file, shadelab::brdfParameterValues(file, entry.Overrides)));
      }
    }
  });
  if (!filesReady)
  {
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

  // The curves of the models drawn, no others.
  vtkNew<slAlbedoTable> albedoTable;
  slCopyMaterialNumbers(this->LobeParameters.Get(), albedoTable.Get());
  albedoTable->SetNumberOfAngles(kAlbedoCurveAngles);
  albedoTable->DisableAllModels();
  for (const Entry& entry : this->Entries)
  {
    if (entry.Model >= 0)
    {
      albedoTable->SetModelEnabled(entry.Model, true);
    }
  }
  albedoTable->Update();
  vtkTable* curves = albedoTable->GetOutput();
  vtkAbstractArray* degrees = curves->GetColumnByName("IncidenceDegrees");

  std::vector<double> fileAlbedos;
  double extent = 0.0;
  size_t fileIndex = 0;
  for (size_t i = 0; i < this->Entries.size(); ++i)
  {
    const Entry& entry = this->Entries[i];
    const unsigned char* rgb = kPalette[i];
    const std::string name = entry.Model >= 0
      ? std::string(shadelab::modelName(static_cast<shadelab::ShadingModel>(entry.Model)))
      : shadelab::brdfDisplayName(entry.Path);
    vtkNew<slBRDFLobeSource> lobe;
    slBRDFLobeSource* p = this->LobeParameters;
    lobe->SetModel(entry.Model >= 0 ? entry.Model : p->GetModel());
    slCopyMaterialNumbers(p, lobe.Get());
    lobe->SetIncidenceAngle(p->GetIncidenceAngle());
    lobe->SetDiffuseWeight(p->GetDiffuseWeight());
    lobe->SetSpecularWeight(p->GetSpecularWeight());
    lobe->SetMultiplyByCosine(p->GetMultiplyByCosine());
    lobe->SetThetaResolution(p->GetThetaResolution());
    lobe->SetPhiResolution(p->GetPhiResolution());
    vtkSmartPointer<vtkTable> fileCurve;
    if (entry.Model < 0)
    {
      slBRDFFileEvaluator& evaluator = *evaluators[fileIndex++];
      fileCurve = vtkSmartPointer<vtkTable>::New();
      vtkNew<vtkFloatArray> xs, ys;
      xs->SetName("IncidenceDegrees");
      ys->SetName(name.c_str());
      const bool evaluated = slRunCore(this, [&] {
        evaluator.SetLobeValues(lobe);
        for (vtkIdType row = 0; row < degrees->GetNumberOfTuples(); ++row)
        {
          const double angle = degrees->GetVariantValue(row).ToDouble();
          xs->InsertNextValue(static_cast<float>(angle));
          ys->InsertNextValue(static_cast<float>(evaluator.AlbedoAtIncidence(angle)));
        }
        fileAlbedos.push_back(evaluator.AlbedoAtIncidence(p->GetIncidenceAngle()));
      });
      if (!evaluated)
      {
        return false;
      }
      fileCurve->AddColumn(xs);
      fileCurve->AddColumn(ys);
    }
    lobe->Update();

    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(lobe->GetOutputPort(0));
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0);
    actor->GetProperty()->SetOpacity(this->Entries.size() > 1 ? 0.55 : 1.0);
    lobes->AddActor(actor);
    const double* b = lobe->GetOutput(0)->GetBounds();
    extent = std::max({ extent, std::abs(b[0]), std::abs(b[1]), std::abs(b[5]) });

    // Polar slice: the slice's points in the x-z plane.
    vtkPolyData* slice = lobe->GetSliceOutput();
    vtkNew<vtkTable> table;
    vtkNew<vtkFloatArray> xs, zs;
    xs->SetName("x");
    zs->SetName(name.c_str());
    for (vtkIdType k = 0; k < slice->GetNumberOfPoints(); ++k)
    {
      double point[3];
      slice->GetPoint(k, point);
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
    if (fileCurve)
    {
      curve->SetInputData(fileCurve, 0, 1);
    }
    else
    {
      curve->SetInputData(curves, "IncidenceDegrees", name);
    }
    curve->SetColor(rgb[0], rgb[1], rgb[2], 255);
    curve->SetWidth(2.0);
  }
  this->FileAlbedos = fileAlbedos;

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
  // A window that cannot be drawn is an error, not a black image.
  return slRunCore(this, [&] { this->Image = slCaptureWindow(window); });
}

void slLobeImageRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Models and files:";
  for (const Entry& entry : this->Entries)
  {
    os << " " << (entry.Model >= 0 ? shadelab::modelName(static_cast<shadelab::ShadingModel>(entry.Model)) : entry.Path);
    for (const std::string& o : entry.Overrides)
    {
      os << " --param " << o;
    }
  }
  os << "\n" << indent << "LobeParameters:\n";
  this->LobeParameters->PrintSelf(os, indent.GetNextIndent());
}
