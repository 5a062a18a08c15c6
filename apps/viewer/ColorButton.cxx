#include "ColorButton.h"

#include <QColorDialog>
#include <QHBoxLayout>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>

#include <algorithm>
#include <cmath>

namespace shadelab
{
namespace viewer
{

namespace
{
constexpr int kSliderSteps = 1000;

float largestOf(const glm::vec3& v)
{
  return std::max(v.x, std::max(v.y, v.z));
}

QColor toQColor(const glm::vec3& v)
{
  const glm::vec3 c = glm::clamp(v, 0.0f, 1.0f);
  return QColor::fromRgbF(c.x, c.y, c.z);
}
} // namespace

ColorButton::ColorButton(QWidget* parent)
  : QWidget(parent)
  , Swatch(new QPushButton(this))
  , Brightness(new QSlider(Qt::Horizontal, this))
{
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  this->Swatch->setFixedWidth(36);
  this->Swatch->setToolTip(tr("Choose the colour"));
  this->Brightness->setRange(0, kSliderSteps);
  this->Brightness->setToolTip(tr("Brightness: the largest component, hue kept"));
  layout->addWidget(this->Swatch);
  layout->addWidget(this->Brightness, 1);
  connect(this->Swatch, &QPushButton::clicked, this, &ColorButton::pickColour);
  connect(this->Brightness, &QSlider::valueChanged, this, &ColorButton::setBrightness);
  this->show(this->Value);
}

void ColorButton::setValue(const glm::vec3& value)
{
  this->Value = value;
  this->show(value);
}

void ColorButton::show(const glm::vec3& value)
{
  this->Swatch->setStyleSheet(QString("background-color: %1").arg(toQColor(value).name()));
  const QSignalBlocker block(this->Brightness);
  this->Brightness->setValue(static_cast<int>(std::lround(largestOf(value) * kSliderSteps)));
}

void ColorButton::pickColour()
{
  const glm::vec3 before = this->Value;
  QColorDialog dialog(toQColor(before), this);
  connect(&dialog, &QColorDialog::currentColorChanged, this, [this](const QColor& c) {
    this->Value = glm::vec3(c.redF(), c.greenF(), c.blueF());
    this->show(this->Value);
    emit valueChanged(this->Value);
  });
  if (dialog.exec() != QDialog::Accepted)
  {
    this->Value = before; // cancelled: undo the live preview
    this->show(before);
    emit valueChanged(before);
  }
}

void ColorButton::setBrightness(int sliderValue)
{
  const float target = static_cast<float>(sliderValue) / kSliderSteps;
  const float largest = largestOf(this->Value);
  this->Value = largest > 0.0f ? this->Value * (target / largest) : glm::vec3(target);
  this->show(this->Value);
  emit valueChanged(this->Value);
}

} // namespace viewer
} // namespace shadelab
