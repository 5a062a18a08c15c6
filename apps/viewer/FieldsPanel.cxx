#include "FieldsPanel.h"

#include "ReferenceJob.h"
#include "SceneView.h"
#include "ViewerDocument.h"

#include "slCosineField.h"
#include "slRadianceFilter.h"
#include "slSceneTexture.h"
#include "slScene.h"
#include "slUpdateOrThrow.h"

#include <vtkImageData.h>
#include <vtkPolyData.h>

#include <QComboBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>

namespace shadelab
{
namespace viewer
{

namespace
{
/// The chooser's entries: label, array, and where it comes from.
enum class Source
{
  None,
  Cosine,
  Radiance,
  Reference
};
struct FieldEntry
{
  const char* label;
  const char* array;
  Source source;
};
const FieldEntry kFields[] = {
  { "none: the lit view", "", Source::None },
  { "N.L clamped (CosTheta)", "CosTheta", Source::Cosine },
  { "N.L raw, < 0 faces away (CosThetaRaw)", "CosThetaRaw", Source::Cosine },
  { "Diffuse", "Diffuse", Source::Radiance },
  { "Specular", "Specular", Source::Radiance },
  { "Radiance (discrete lights)", "Radiance", Source::Radiance },
  { "Reference radiance (Monte Carlo)", "Radiance", Source::Reference },
  { "Reference - discrete (RadianceError)", "RadianceError", Source::Reference },
  { "Reference standard error", "RadianceStdError", Source::Reference },
};
} // namespace

FieldsPanel::FieldsPanel(ViewerDocument* document, SceneView* view, QWidget* parent)
  : QWidget(parent)
  , Document(document)
  , View(view)
  , Field(new QComboBox(this))
  , Light(new QSpinBox(this))
  , Samples(new QSpinBox(this))
  , Strategy(new QComboBox(this))
  , Environment(new QLineEdit(this))
  , Compute(new QPushButton(tr("Compute reference"), this))
  , Cancel(new QPushButton(tr("Cancel"), this))
  , Progress(new QProgressBar(this))
  , Status(new QLabel(this))
  , Job(new ReferenceJob(this))
{
  for (const FieldEntry& entry : kFields)
  {
    this->Field->addItem(tr(entry.label));
  }
  this->Light->setToolTip(tr("The light whose N.L is shown"));
  this->Samples->setRange(1, 1 << 20);
  this->Samples->setValue(64);
  this->Strategy->addItems({ tr("uniform"), tr("cosine"), tr("BRDF"), tr("light"), tr("MIS") });
  this->Strategy->setCurrentIndex(4);
  this->Environment->setPlaceholderText(tr("none (scene lights only)"));
  auto* browse = new QPushButton(tr("..."), this);
  this->Cancel->setEnabled(false);
  this->Progress->setRange(0, 100);
  this->Progress->setValue(0);
  this->Status->setWordWrap(true);

  auto* form = new QFormLayout(this);
  form->addRow(tr("Field"), this->Field);
  form->addRow(tr("N.L of light"), this->Light);
  form->addRow(new QLabel(tr("<b>Radiance-equation reference</b>"), this));
  form->addRow(tr("Samples per point"), this->Samples);
  form->addRow(tr("Sampling"), this->Strategy);
  auto* environmentRow = new QHBoxLayout;
  environmentRow->addWidget(this->Environment, 1);
  environmentRow->addWidget(browse);
  form->addRow(tr("Environment map"), environmentRow);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(this->Compute);
  buttons->addWidget(this->Cancel);
  form->addRow(buttons);
  form->addRow(this->Progress);
  form->addRow(this->Status);

  connect(this->Field, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &FieldsPanel::showField);
  connect(this->Light, QOverload<int>::of(&QSpinBox::valueChanged), this, &FieldsPanel::showField);
  connect(browse, &QPushButton::clicked, this, [this] {
    const QString file = QFileDialog::getOpenFileName(
      this, tr("Environment map"), QString(), tr("HDR images (*.hdr *.exr);;All files (*)"));
    if (!file.isEmpty())
    {
      this->Environment->setText(file);
    }
  });
  connect(this->Compute, &QPushButton::clicked, this, &FieldsPanel::startReference);
  connect(this->Cancel, &QPushButton::clicked, this->Job, &ReferenceJob::cancel);
  connect(this->Job, &ReferenceJob::progress, this->Progress, &QProgressBar::setValue);
  connect(this->Job, &ReferenceJob::finished, this, &FieldsPanel::referenceFinished);
  connect(document, &ViewerDocument::sceneChanged, this, [this](int changes) {
    this->showLightCount();
    if (changes & (MaterialChange | LightsChange | ShadingChange | CameraChange))
    {
      this->lightingChanged();
    }
  });
  // Other normals (or tangents) light the mesh otherwise: the fields follow,
  // computed on the mesh the view lights now (which the lit view makes).
  const auto remeshed = [this] {
    if (this->View->mode() == SceneView::FieldMode)
    {
      this->View->setMode(SceneView::LitMode);
    }
    this->lightingChanged();
  };
  connect(document, &ViewerDocument::normalsChanged, this, remeshed);
  connect(document, &ViewerDocument::tangentsChanged, this, remeshed);
  connect(document, &ViewerDocument::meshChanged, this, [this] {
    // A reference of the mesh that was shown is no field of this one, nor
    // is one still being computed for it.
    ++this->MeshGeneration;
    this->Job->cancel();
    this->Reference = nullptr;
    this->Field->setCurrentIndex(0);
  });
  this->showLightCount();
}

void FieldsPanel::showLightCount()
{
  const int count = static_cast<int>(this->Document->scene().lights.size());
  this->Light->setMaximum(std::max(0, count - 1));
}

void FieldsPanel::lightingChanged()
{
  this->ReferenceStale = this->Reference != nullptr;
  this->ChangedWhileRunning = this->Job->running();
  if (this->Field->currentIndex() > 0)
  {
    this->showField();
  }
}

FieldsPanel::~FieldsPanel()
{
  this->Job->cancel();
  this->Job->wait();
}

vtkPolyData* FieldsPanel::reference() const
{
  return this->Reference;
}

void FieldsPanel::showField()
{
  const FieldEntry& entry = kFields[this->Field->currentIndex()];
  vtkPolyData* mesh = this->View->meshWithNormals();
  if (entry.source == Source::None || !mesh)
  {
    this->View->setField(nullptr, QString());
    return;
  }
  vtkSmartPointer<vtkPolyData> fields;
  if (entry.source == Source::Reference)
  {
    if (!this->Reference)
    {
      this->Status->setText(tr("Compute the reference first."));
      return;
    }
    this->Status->setText(this->ReferenceStale ? tr("The scene changed since the reference was computed.") : QString());
    fields = this->Reference;
  }
  else
  {
    vtkSmartPointer<slLitFilter> filter;
    try
    {
      if (entry.source == Source::Cosine)
      {
        auto cosine = vtkSmartPointer<slCosineField>::New();
        cosine->SetLightIndex(this->Light->value()); // the box's range is the scene's lights
        filter = cosine;
      }
      else
      {
        // The scene's diffuse texture, as the view draws it and the
        // reference applies it.
        auto radiance = vtkSmartPointer<slRadianceFilter>::New();
        radiance->SetDiffuseTexture(slSceneTextureFor(slReadSceneTexture(this->Document->vtkScene()), mesh));
        filter = radiance;
      }
      filter->SetInputData(mesh);
      filter->SetScene(this->Document->vtkScene());
      filter->SetCamera(this->View->camera());
      filter->ZeroNormalsAreErrorsOff();
      slUpdateOrThrow(filter);
    }
    catch (const shadelab::Error& e)
    {
      emit problem(QString::fromUtf8(e.what()));
      return;
    }
    fields = filter->GetOutput();
  }
  this->View->setField(fields, QString::fromUtf8(entry.array));
}

void FieldsPanel::startReference()
{
  vtkPolyData* mesh = this->View->meshWithNormals();
  if (!mesh)
  {
    emit problem(tr("open a mesh first"));
    return;
  }
  ReferenceSettings settings;
  settings.samplesPerPoint = this->Samples->value();
  settings.strategy = this->Strategy->currentIndex();
  settings.environmentMap = this->Environment->text();
  if (this->Job->start(mesh, this->Document->scene(), this->View->camera(), settings))
  {
    this->JobMeshGeneration = this->MeshGeneration;
    this->ChangedWhileRunning = false;
    this->Compute->setEnabled(false);
    this->Cancel->setEnabled(true);
    this->Progress->setValue(0);
    this->Status->setText(tr("Computing..."));
  }
}

void FieldsPanel::referenceFinished(const QString& error)
{
  this->Compute->setEnabled(true);
  this->Cancel->setEnabled(false);
  if (this->JobMeshGeneration != this->MeshGeneration)
  {
    this->Progress->setValue(0);
    this->Status->setText(tr("Another mesh was opened: compute its reference."));
    return;
  }
  if (!error.isEmpty())
  {
    this->Progress->setValue(0);
    this->Status->setText(tr("Reference: %1").arg(error));
    if (error != tr("cancelled"))
    {
      emit problem(error);
    }
    return;
  }
  this->Reference = this->Job->result();
  this->ReferenceStale = this->ChangedWhileRunning;
  this->Status->setText(tr("Reference done."));
  if (kFields[this->Field->currentIndex()].source != Source::Reference)
  {
    this->Field->setCurrentIndex(6); // show what was just computed
  }
  else
  {
    this->showField();
  }
}

} // namespace viewer
} // namespace shadelab
