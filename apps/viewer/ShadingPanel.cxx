#include "ShadingPanel.h"

#include "ColorButton.h"
#include "SceneView.h"
#include "ViewerDocument.h"
#include "shadelab/ValueLimits.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>

namespace shadelab
{
namespace viewer
{

ShadingPanel::ShadingPanel(ViewerDocument* document, SceneView* view, QWidget* parent)
  : QWidget(parent)
  , Document(document)
  , Model(new QComboBox(this))
  , Frequency(new QComboBox(this))
  , Split(new QCheckBox(tr("flat | Gouraud | Phong side by side"), this))
  , Background(new ColorButton(0.0, shadelab::kMaxColourValue, this)) // the scene key's range
  , Tangents(new QLabel(this))
  , ComputeTangents(new QPushButton(tr("Compute tangents"), this))
{
  for (const std::string& name : modelNames())
  {
    this->Model->addItem(QString::fromStdString(name));
  }
  for (const std::string& name : frequencyNames())
  {
    this->Frequency->addItem(QString::fromStdString(name));
  }
  auto* form = new QFormLayout(this);
  form->addRow(tr("Model"), this->Model);
  this->Tangents->setWordWrap(true);
  form->addRow(this->Tangents);
  form->addRow(this->ComputeTangents);
  form->addRow(tr("Frequency"), this->Frequency);
  form->addRow(tr("Split view"), this->Split);
  form->addRow(tr("Background"), this->Background);

  connect(this->Model, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int index) {
    Scene scene = this->Document->scene();
    scene.model = static_cast<ShadingModel>(index);
    this->Document->setScene(scene, ShadingChange);
  });
  connect(this->Frequency, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int index) {
    Scene scene = this->Document->scene();
    scene.frequency = static_cast<ShadingFrequency>(index);
    this->Document->setScene(scene, ShadingChange);
  });
  connect(this->Split, &QCheckBox::toggled, view,
    [view](bool on) { view->setMode(on ? SceneView::SplitMode : SceneView::LitMode); });
  connect(this->Background, &ColorButton::valueChanged, this, [this](const glm::vec3& value) {
    Scene scene = this->Document->scene();
    scene.background = value;
    this->Document->setScene(scene, BackgroundChange);
  });
  connect(this->ComputeTangents, &QPushButton::clicked, this, [this] {
    QString error;
    if (this->Document->computeTangents(error))
    {
      emit notice(tr("Computed the mesh's tangents from its texture coordinates"));
    }
    else
    {
      emit problem(error);
    }
  });
  connect(document, &ViewerDocument::sceneChanged, this, &ShadingPanel::showScene);
  connect(document, &ViewerDocument::meshChanged, this, &ShadingPanel::showTangents);
  connect(document, &ViewerDocument::tangentsChanged, this, &ShadingPanel::showTangents);
  this->showScene();
}

void ShadingPanel::showTangents()
{
  const QString line = this->Document->tangentsProblem();
  const bool changed = line != this->Tangents->text();
  this->Tangents->setText(line);
  this->Tangents->setVisible(!line.isEmpty());
  this->ComputeTangents->setVisible(!line.isEmpty());
  this->ComputeTangents->setEnabled(this->Document->canComputeTangents());
  if (changed && !line.isEmpty())
  {
    emit notice(line);
  }
}

void ShadingPanel::showScene()
{
  const Scene& scene = this->Document->scene();
  const QSignalBlocker blockModel(this->Model);
  const QSignalBlocker blockFrequency(this->Frequency);
  this->Model->setCurrentIndex(static_cast<int>(scene.model));
  this->Frequency->setCurrentIndex(static_cast<int>(scene.frequency));
  this->Background->setValue(scene.background);
  this->showTangents();
}

} // namespace viewer
} // namespace shadelab
