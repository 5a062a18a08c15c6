#include "ColorButton.h"

#include <QColorDialog>
#include <QDoubleSpinBox>
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
/// Decimals of the brightness spin box: a thousandth of a unit reflectance.
constexpr int kDecimals = 3;

float largestOf(const glm::vec3& v)
{
  return std::max(v.x, std::max(v.y, v.z));
}

/// What a screen can show of @p v: the colour divided by its brightness
/// when that is above 1, so that 2 2 2 shows white and 3 1.5 0 orange.
glm::vec3 hueOf(const glm::vec3& v)
{
  const float brightness = largestOf(v);
  return brightness > 1.0f ? v / brightness : v;
}

QColor toQColor(const glm::vec3& v)
{
  const glm::vec3 c = glm::clamp(hueOf(v), 0.0f, 1.0f);
  return QColor::fromRgbF(c.x, c.y, c.z);
}
} // namespace

ColorButton::ColorButton(QWidget* parent)
  : ColorButton(0.0, 1.0, parent)
{
}

ColorButton::ColorButton(double lo, double hi, QWidget* parent)
  : QWidget(parent)
  , Lo(lo)
  , SliderHi(lo < 1.0 ? std::min(hi, 1.0) : hi)
  , Swatch(new QPushButton(this))
  , Brightness(new QSlider(Qt::Horizontal, this))
  , Box(new QDoubleSpinBox(this))
{
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  this->Swatch->setFixedWidth(36);
  this->Brightness->setRange(0, kSliderSteps);
  this->Brightness->setToolTip(tr("Brightness: the largest component, hue kept"));
  this->Box->setRange(lo, hi);
  this->Box->setDecimals(kDecimals);
  this->Box->setSingleStep(0.01);
  // A value when typing ends: "0" on the way to "0.5" would lose the hue.
  this->Box->setKeyboardTracking(false);
  this->Box->setToolTip(tr("Brightness: the largest component, hue kept; up to %1").arg(hi));
  layout->addWidget(this->Swatch);
  layout->addWidget(this->Brightness, 1);
  layout->addWidget(this->Box);
  connect(this->Swatch, &QPushButton::clicked, this, &ColorButton::pickColour);
  connect(this->Brightness, &QSlider::valueChanged, this, [this](int position) {
    this->setBrightness(this->Lo + (this->SliderHi - this->Lo) * position / kSliderSteps);
  });
  connect(this->Box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, &ColorButton::setBrightness);
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
  this->Swatch->setToolTip(
    tr("Choose the colour (now %1 %2 %3)").arg(value.x).arg(value.y).arg(value.z));
  const QSignalBlocker blockSlider(this->Brightness);
  const QSignalBlocker blockBox(this->Box);
  const double brightness = largestOf(value);
  const double t = this->SliderHi > this->Lo ? (brightness - this->Lo) / (this->SliderHi - this->Lo) : 0.0;
  this->Brightness->setValue(static_cast<int>(std::lround(kSliderSteps * std::clamp(t, 0.0, 1.0))));
  this->Box->setValue(brightness);
}

void ColorButton::pickColour()
{
  const glm::vec3 before = this->Value;
  // The dialog's colours stop at 1: it picks the hue, and a brightness above 1 stays.
  const float scale = std::max(1.0f, largestOf(before));
  QColorDialog dialog(toQColor(before), this);
  connect(&dialog, &QColorDialog::currentColorChanged, this, [this, scale](const QColor& c) {
    this->Value = glm::vec3(c.redF(), c.greenF(), c.blueF()) * scale;
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

void ColorButton::setBrightness(double brightness)
{
  const float target = static_cast<float>(brightness);
  const float largest = largestOf(this->Value);
  this->Value = largest > 0.0f ? this->Value * (target / largest) : glm::vec3(target);
  this->show(this->Value);
  emit valueChanged(this->Value);
}

} // namespace viewer
} // namespace shadelab
