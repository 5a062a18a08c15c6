#include "LightPanel.h"

#include "ColorButton.h"
#include "LightWidgets.h"
#include "SceneView.h"
#include "ViewerDocument.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QVBoxLayout>

namespace shadelab
{
namespace viewer
{

namespace
{
QString describe(const SceneLight& light, size_t index)
{
  const QString name = light.name.empty() ? QString("light %1").arg(index) : QString::fromStdString(light.name);
  return QString("%1 (%2%3)")
    .arg(name, lightTypeName(light.type), light.space == LightSpace::Camera ? ", camera" : "");
}

QHBoxLayout* rowOf(QDoubleSpinBox* const (&boxes)[3])
{
  auto* row = new QHBoxLayout;
  for (QDoubleSpinBox* box : boxes)
  {
    row->addWidget(box);
  }
  return row;
}
} // namespace

QDoubleSpinBox* LightPanel::spinBox(double minimum, double maximum, int decimals)
{
  auto* box = new QDoubleSpinBox(this->Editor);
  box->setRange(minimum, maximum);
  box->setDecimals(decimals);
  box->setSingleStep(maximum > 100.0 ? 0.1 : 0.05);
  box->setKeyboardTracking(false);
  connect(box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, &LightPanel::editLight);
  return box;
}

LightPanel::LightPanel(ViewerDocument* document, SceneView* view, QWidget* parent)
  : QWidget(parent)
  , Document(document)
  , List(new QListWidget(this))
  , Add(new QPushButton(tr("Add"), this))
  , Remove(new QPushButton(tr("Remove"), this))
  , ShowWidgets(new QCheckBox(tr("Show and drag lights in the view"), this))
  , Editor(new QWidget(this))
  , Name(new QLineEdit(this->Editor))
  , Type(new QComboBox(this->Editor))
  , Space(new QComboBox(this->Editor))
{
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(this->List, 1);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(this->Add);
  buttons->addWidget(this->Remove);
  layout->addLayout(buttons);
  layout->addWidget(this->ShowWidgets);
  layout->addWidget(this->Editor);

  auto* addMenu = new QMenu(this->Add);
  for (const std::string& type : lightTypeNames())
  {
    const QString name = QString::fromStdString(type);
    addMenu->addAction(name, this, [this, name] { this->addLight(name); });
    this->Type->addItem(name);
  }
  this->Add->setMenu(addMenu);
  for (const std::string& space : lightSpaceNames())
  {
    this->Space->addItem(QString::fromStdString(space));
  }

  auto* form = new QFormLayout(this->Editor);
  form->setContentsMargins(0, 0, 0, 0);
  form->addRow(tr("Name"), this->Name);
  form->addRow(tr("Type"), this->Type);
  form->addRow(tr("Space"), this->Space);
  const char* const colourNames[3] = { "Ambient", "Diffuse", "Specular" };
  for (int k = 0; k < 3; ++k)
  {
    this->Colours[k] = new ColorButton(this->Editor);
    form->addRow(tr(colourNames[k]), this->Colours[k]);
    connect(this->Colours[k], &ColorButton::valueChanged, this, &LightPanel::editLight);
  }
  this->Intensity = this->spinBox(0.0, 1.0e4, 3);
  form->addRow(tr("Intensity"), this->Intensity);
  for (int i = 0; i < 3; ++i)
  {
    this->Attenuation[i] = this->spinBox(0.0, 1.0e4, 4);
    this->Position[i] = this->spinBox(-1.0e6, 1.0e6, 3);
    this->Direction[i] = this->spinBox(-1.0e6, 1.0e6, 3);
  }
  form->addRow(tr("Attenuation c1 c2 c3"), rowOf(this->Attenuation));
  this->Cutoff = this->spinBox(0.1, 90.0, 1);
  this->Exponent = this->spinBox(0.0, 1000.0, 2);
  this->Edge = this->spinBox(0.0, 90.0, 1);
  form->addRow(tr("Spot cutoff (deg)"), this->Cutoff);
  form->addRow(tr("Spot exponent"), this->Exponent);
  form->addRow(tr("Spot smooth edge (deg)"), this->Edge);
  form->addRow(tr("Position"), rowOf(this->Position));
  form->addRow(tr("Direction"), rowOf(this->Direction));

  this->ShowWidgets->setChecked(view->lightWidgets()->enabled());
  connect(this->ShowWidgets, &QCheckBox::toggled, view, &SceneView::setLightWidgets);
  connect(this->Remove, &QPushButton::clicked, this, &LightPanel::removeSelectedLight);
  connect(this->List, &QListWidget::currentRowChanged, this, &LightPanel::showLight);
  connect(this->Name, &QLineEdit::editingFinished, this, &LightPanel::editLight);
  connect(this->Type, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &LightPanel::editLight);
  connect(this->Space, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &LightPanel::editLight);
  connect(document, &ViewerDocument::sceneChanged, this, &LightPanel::showScene);
  this->showScene();
}

void LightPanel::addLight(const QString& typeName)
{
  Scene scene = this->Document->scene();
  SceneLight light;
  parseLightTypeName(typeName.toStdString(), light.type);
  light.name = typeName.toStdString() + " " + std::to_string(scene.lights.size());
  if (!lightTakes(light.type, kLightDiffuse))
  {
    // It lights k_a only.
    light.ambient = glm::vec3(0.1f);
    light.diffuse = light.specular = glm::vec3(0.0f);
  }
  // A camera light from above the viewer's right shoulder: visible at once.
  light.space = LightSpace::Camera;
  light.position = glm::vec3(0.5f, 0.5f, 1.0f);
  light.direction = -light.position;
  scene.lights.push_back(light);
  this->Document->setScene(scene, LightsChange);
  this->List->setCurrentRow(static_cast<int>(scene.lights.size()) - 1);
}

void LightPanel::removeSelectedLight()
{
  const int row = this->List->currentRow();
  Scene scene = this->Document->scene();
  if (row < 0 || row >= static_cast<int>(scene.lights.size()))
  {
    return;
  }
  scene.lights.erase(scene.lights.begin() + row);
  this->Document->setScene(scene, LightsChange);
}

void LightPanel::showScene()
{
  const Scene& scene = this->Document->scene();
  const int row = this->List->currentRow();
  this->Showing = true;
  this->List->clear();
  for (size_t i = 0; i < scene.lights.size(); ++i)
  {
    this->List->addItem(describe(scene.lights[i], i));
  }
  this->Showing = false;
  const int count = static_cast<int>(scene.lights.size());
  this->List->setCurrentRow(count == 0 ? -1 : std::min(std::max(row, 0), count - 1));
  this->showLight(this->List->currentRow());
}

void LightPanel::showLight(int index)
{
  const Scene& scene = this->Document->scene();
  const bool valid = index >= 0 && index < static_cast<int>(scene.lights.size());
  this->Editor->setEnabled(valid);
  this->Remove->setEnabled(valid);
  if (!valid || this->Showing)
  {
    return;
  }
  const SceneLight& l = scene.lights[static_cast<size_t>(index)];
  this->Showing = true;
  this->Name->setText(QString::fromStdString(l.name));
  this->Type->setCurrentText(lightTypeName(l.type));
  this->Space->setCurrentText(lightSpaceName(l.space));
  this->Colours[0]->setValue(l.ambient);
  this->Colours[1]->setValue(l.diffuse);
  this->Colours[2]->setValue(l.specular);
  this->Intensity->setValue(l.intensity);
  for (int i = 0; i < 3; ++i)
  {
    this->Attenuation[i]->setValue(l.attenuation[i]);
    this->Position[i]->setValue(l.position[i]);
    this->Direction[i]->setValue(l.direction[i]);
  }
  this->Cutoff->setValue(l.cutoffDegrees);
  this->Exponent->setValue(l.exponent);
  this->Edge->setValue(l.edgeDegrees);
  // Each control is live for the light types that take its value (LightingTables.h).
  this->Cutoff->setEnabled(lightTakes(l.type, kLightCutoff));
  this->Exponent->setEnabled(lightTakes(l.type, kLightExponent));
  this->Edge->setEnabled(lightTakes(l.type, kLightEdge));
  this->Showing = false;
}

void LightPanel::editLight()
{
  const int index = this->List->currentRow();
  Scene scene = this->Document->scene();
  if (this->Showing || index < 0 || index >= static_cast<int>(scene.lights.size()))
  {
    return;
  }
  SceneLight& l = scene.lights[static_cast<size_t>(index)];
  const LightType typeBefore = l.type;
  l.name = this->Name->text().toStdString();
  parseLightTypeName(this->Type->currentText().toStdString(), l.type);
  parseLightSpaceName(this->Space->currentText().toStdString(), l.space);
  l.ambient = this->Colours[0]->value();
  l.diffuse = this->Colours[1]->value();
  l.specular = this->Colours[2]->value();
  l.intensity = static_cast<float>(this->Intensity->value());
  for (int i = 0; i < 3; ++i)
  {
    l.attenuation[i] = static_cast<float>(this->Attenuation[i]->value());
    l.position[i] = static_cast<float>(this->Position[i]->value());
    l.direction[i] = static_cast<float>(this->Direction[i]->value());
  }
  // Scene files require c1 + c2 + c3 > 0 and edge <= cutoff; keep the light valid.
  if (l.attenuation[0] + l.attenuation[1] + l.attenuation[2] <= 0.0f)
  {
    l.attenuation[0] = 1.0f;
  }
  l.cutoffDegrees = static_cast<float>(this->Cutoff->value());
  l.exponent = static_cast<float>(this->Exponent->value());
  l.edgeDegrees = std::min(static_cast<float>(this->Edge->value()), l.cutoffDegrees);
  this->Document->setScene(scene, LightsChange);
  if (l.type != typeBefore)
  {
    this->showLight(index);
  }
}

} // namespace viewer
} // namespace shadelab
