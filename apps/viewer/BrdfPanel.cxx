#include "BrdfPanel.h"

#include "SceneView.h"
#include "ViewerDocument.h"

#include "slBRDFLobeSource.h"
#include "slLobeImageRenderer.h"
#include "slLobesOnMesh.h"
#include "slScene.h"
#include "slUpdateOrThrow.h"

#include "shadelab/LightingGLSL.h"
#include "shadelab/SceneKeys.h"

#include <vtkCamera.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QPushButton>
#include <QSpinBox>
#include <QStringList>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadelab
{
namespace viewer
{

namespace
{
glm::vec3 vec(const double v[3])
{
  return glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
}

/// An RGB unsigned char vtkImageData (row 0 at the bottom) as a QImage.
QImage toQImage(vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  QImage out(dims[0], dims[1], QImage::Format_RGB888);
  const auto* pixels = static_cast<const unsigned char*>(image->GetScalarPointer());
  for (int y = 0; y < dims[1]; ++y)
  {
    std::copy(pixels + 3 * static_cast<size_t>(y) * dims[0], pixels + 3 * static_cast<size_t>(y + 1) * dims[0],
      out.scanLine(dims[1] - 1 - y));
  }
  return out;
}
} // namespace

BrdfPanel::BrdfPanel(ViewerDocument* document, SceneView* view, QWidget* parent)
  : QWidget(parent)
  , Document(document)
  , View(view)
  , Pick(new QPushButton(tr("Pick a point on the mesh"), this))
  , Light(new QSpinBox(this))
  , Info(new QLabel(tr("No point picked."), this))
  , Picture(new QLabel(this))
  , Pending(new QTimer(this))
{
  this->Pick->setCheckable(true);
  this->Light->setPrefix(tr("light "));
  this->Info->setWordWrap(true);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(this->Pick);
  layout->addWidget(this->Light);
  layout->addWidget(this->Info);
  layout->addWidget(this->Picture, 1);

  connect(this->Pick, &QPushButton::toggled, view, &SceneView::setPicking);
  connect(view, &SceneView::pointPicked, this, &BrdfPanel::showLobeAt);
  connect(this->Light, QOverload<int>::of(&QSpinBox::valueChanged), this, &BrdfPanel::update);
  // A slider drag or a light drag changes the scene many times a second;
  // the lobe and its offscreen picture follow once the edits pause.
  this->Pending->setSingleShot(true);
  this->Pending->setInterval(150);
  connect(this->Pending, &QTimer::timeout, this, &BrdfPanel::update);
  // The light chooser goes from the scene's first light to its last.
  const auto showLightCount = [this] {
    this->Light->setMaximum(std::max(0, static_cast<int>(this->Document->scene().lights.size()) - 1));
  };
  showLightCount();
  connect(document, &ViewerDocument::sceneChanged, this, [this, showLightCount](int changes) {
    showLightCount();
    if (this->Point >= 0 && (changes & (MaterialChange | LightsChange | ShadingChange)))
    {
      this->Pending->start();
    }
  });
  // Tangents may split points at mirror seams: the picked index is stale too.
  const auto forgetPoint = [this] {
    this->Point = -1;
    this->Info->setText(tr("No point picked."));
    this->Picture->clear();
  };
  connect(document, &ViewerDocument::meshChanged, this, forgetPoint);
  connect(document, &ViewerDocument::tangentsChanged, this, forgetPoint);
}

void BrdfPanel::showLobeAt(double x, double y, double z)
{
  vtkPolyData* mesh = this->View->meshWithNormals();
  if (!mesh)
  {
    return;
  }
  double p[3] = { x, y, z };
  this->Point = mesh->FindPoint(p);
  this->update();
}

void BrdfPanel::update()
{
  this->Pending->stop();
  vtkPolyData* mesh = this->View->meshWithNormals();
  const Scene& scene = this->Document->scene();
  if (this->Point < 0 || !mesh || this->Point >= mesh->GetNumberOfPoints())
  {
    return;
  }
  const int light = this->Light->value();
  if (light >= static_cast<int>(scene.lights.size()) || !lightHasDirection(static_cast<int>(scene.lights[light].type)))
  {
    this->Info->setText(tr("Light %1 has no direction: choose a directional, point or spot light.").arg(light));
    this->View->setLobe(nullptr);
    return;
  }

  // The lobe on the mesh, in the point's normal frame.
  vtkNew<vtkIdList> ids;
  ids->InsertNextId(this->Point);
  vtkNew<slLobesOnMesh> lobes;
  lobes->SetInputData(mesh);
  lobes->SetScene(this->Document->vtkScene());
  lobes->SetCamera(this->View->camera());
  lobes->SetLightIndex(light);
  lobes->SetPointIds(ids);
  lobes->SetScale(0.25);
  lobes->ZeroNormalsAreErrorsOff(); // the mesh may have isolated points; the picked one has a normal
  try
  {
    slUpdateOrThrow(lobes);
  }
  catch (const shadelab::Error& e)
  {
    emit problem(QString::fromUtf8(e.what()));
    return;
  }

  // The incidence angle there, from the lighting core.
  vtkCamera* camera = this->View->camera();
  const SceneLight world = lightInWorldSpace(
    scene.lights[light], vec(camera->GetPosition()), vec(camera->GetFocalPoint()), vec(camera->GetViewUp()));
  double point[3], normal[3];
  mesh->GetPoint(this->Point, point);
  mesh->GetPointData()->GetNormals()->GetTuple(this->Point, normal);
  const float cosTheta =
    glsl::slCosTheta(toEvaluationLight(world), vec(point), glsl::slSafeNormalize(vec(normal)));
  this->Incidence = cosTheta > 0.0f ? glm::degrees(std::acos(std::min(1.0f, cosTheta)))
                                    : std::numeric_limits<double>::quiet_NaN();
  this->View->setLobe(lobes->GetOutput());
  if (!(cosTheta > 0.0f))
  {
    this->Info->setText(tr("Point %1: the light is below its horizon (N.L = %2): no lobe.")
                          .arg(this->Point)
                          .arg(cosTheta, 0, 'f', 3));
    this->Picture->clear();
    return;
  }
  // The numbers the model reads, from the material table.
  QStringList numbers;
  vtkNew<slLobeImageRenderer> picture;
  picture->AddModel(modelName(scene.model));
  slBRDFLobeSource* parameters = picture->GetLobeParameters();
  for (const SceneKey<SceneMaterial>& key : materialKeys())
  {
    if (key.number)
    {
      const float value = scene.material.*(key.number);
      parameters->SetMaterialParameter(key.name, value);
      if (modelInfo(scene.model).reads & key.materialParameter)
      {
        numbers << QString("%1 = %2").arg(QString::fromUtf8(key.name)).arg(value);
      }
    }
  }
  this->Info->setText(tr("Point %1: N.L = %2, incidence %3\u00b0, %4 %5")
                        .arg(this->Point)
                        .arg(cosTheta, 0, 'f', 3)
                        .arg(this->Incidence, 0, 'f', 1)
                        .arg(modelName(scene.model))
                        .arg(numbers.join(", ")));

  parameters->SetIncidenceAngle(this->Incidence);
  parameters->SetDiffuseWeight(glsl::slLuminance(scene.material.diffuse));
  parameters->SetSpecularWeight(glsl::slLuminance(scene.material.specular));
  picture->SetPanelWidth(320);
  picture->SetPanelHeight(240);
  try
  {
    slCallOrThrow(picture, [&] { return picture->Render(); });
  }
  catch (const shadelab::Error& e)
  {
    emit problem(QString::fromUtf8(e.what()));
    return;
  }
  this->Picture->setPixmap(QPixmap::fromImage(toQImage(picture->GetImage())));
}

} // namespace viewer
} // namespace shadelab
