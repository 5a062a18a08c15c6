#include "MaterialPanel.h"

#include "ColorButton.h"
#include "ViewerDocument.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSlider>

#include <cmath>

namespace shadelab
{
namespace viewer
{

namespace
{
constexpr double kMaxShininess = 4096.0;
constexpr int kSteps = 1000;

glm::vec3& coefficient(SceneMaterial& m, int k)
{
  glm::vec3* all[4] = { &m.ambient, &m.diffuse, &m.specular, &m.emission };
  return *all[k];
}
} // namespace

double MaterialPanel::shininessAt(int sliderValue)
{
  return std::pow(kMaxShininess, static_cast<double>(sliderValue) / kSteps);
}

int MaterialPanel::sliderAt(double shininess)
{
  return static_cast<int>(std::lround(kSteps * std::log(std::max(1.0, shininess)) / std::log(kMaxShininess)));
}

MaterialPanel::MaterialPanel(ViewerDocument* document, QWidget* parent)
  : QWidget(parent)
  , Document(document)
  , ShininessSlider(new QSlider(Qt::Horizontal, this))
  , ShininessBox(new QDoubleSpinBox(this))
{
  auto* form = new QFormLayout(this);
  const char* const names[4] = { "Ambient k_a", "Diffuse k_d", "Specular k_s", "Emission k_e" };
  for (int k = 0; k < 4; ++k)
  {
    this->Coefficients[k] = new ColorButton(this);
    form->addRow(tr(names[k]), this->Coefficients[k]);
    connect(this->Coefficients[k], &ColorButton::valueChanged, this, [this, k](const glm::vec3& value) {
      Scene scene = this->Document->scene();
      coefficient(scene.material, k) = value;
      this->Document->setScene(scene, MaterialChange);
    });
  }
  this->ShininessSlider->setRange(0, kSteps);
  this->ShininessBox->setRange(0.0, 10000.0);
  this->ShininessBox->setDecimals(1);
  auto* row = new QHBoxLayout;
  row->addWidget(this->ShininessSlider, 1);
  row->addWidget(this->ShininessBox);
  form->addRow(tr("Shininess n"), row);
  connect(this->ShininessSlider, &QSlider::valueChanged, this,
    [this](int value) { this->setShininess(shininessAt(value)); });
  connect(this->ShininessBox, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
    &MaterialPanel::setShininess);
  connect(document, &ViewerDocument::sceneChanged, this, &MaterialPanel::showScene);
  this->showScene();
}

void MaterialPanel::setShininess(double shininess)
{
  Scene scene = this->Document->scene();
  if (scene.material.shininess == static_cast<float>(shininess))
  {
    return;
  }
  scene.material.shininess = static_cast<float>(shininess);
  this->Document->setScene(scene, MaterialChange);
}

void MaterialPanel::showScene()
{
  const SceneMaterial& m = this->Document->scene().material;
  SceneMaterial copy = m;
  for (int k = 0; k < 4; ++k)
  {
    this->Coefficients[k]->setValue(coefficient(copy, k));
  }
  const QSignalBlocker blockSlider(this->ShininessSlider);
  const QSignalBlocker blockBox(this->ShininessBox);
  this->ShininessSlider->setValue(sliderAt(m.shininess));
  this->ShininessBox->setValue(m.shininess);
}

} // namespace viewer
} // namespace shadelab
