#include "ShadingPanel.h"

#include "ColorButton.h"
#include "SceneView.h"
#include "ViewerDocument.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
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
  , Background(new ColorButton(this))
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
  connect(document, &ViewerDocument::sceneChanged, this, &ShadingPanel::showScene);
  this->showScene();
}

void ShadingPanel::showScene()
{
  const Scene& scene = this->Document->scene();
  const QSignalBlocker blockModel(this->Model);
  const QSignalBlocker blockFrequency(this->Frequency);
  this->Model->setCurrentIndex(static_cast<int>(scene.model));
  this->Frequency->setCurrentIndex(static_cast<int>(scene.frequency));
  this->Background->setValue(scene.background);
}

} // namespace viewer
} // namespace shadelab
