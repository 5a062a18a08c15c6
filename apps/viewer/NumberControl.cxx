#include "NumberControl.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
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
constexpr int kSteps = 1000;
constexpr double kLogarithmicAbove = 1000.0; ///< hi / max(lo, 1) beyond three decades
} // namespace

NumberControl::NumberControl(double lo, double hi, QWidget* parent)
  : QWidget(parent)
  , Lo(lo)
  , Hi(hi)
  , Logarithmic(hi / std::max(lo, 1.0) > kLogarithmicAbove)
  , Slider(new QSlider(Qt::Horizontal, this))
  , Box(new QDoubleSpinBox(this))
{
  this->Slider->setRange(0, kSteps);
  this->Box->setRange(lo, hi);
  // Three significant digits over a unit range, one decimal over exponents.
  this->Box->setDecimals(this->Logarithmic ? 1 : 3);
  this->Box->setSingleStep(this->Logarithmic ? 1.0 : (hi - lo) / 100.0);
  auto* row = new QHBoxLayout(this);
  row->setContentsMargins(0, 0, 0, 0);
  row->addWidget(this->Slider, 1);
  row->addWidget(this->Box);
  connect(this->Slider, &QSlider::valueChanged, this, [this](int position) { this->set(this->valueAt(position)); });
  connect(this->Box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, &NumberControl::set);
}

double NumberControl::valueAt(int position) const
{
  const double t = static_cast<double>(position) / kSteps;
  if (this->Logarithmic)
  {
    const double from = std::max(this->Lo, 1.0);
    return from * std::pow(this->Hi / from, t);
  }
  return this->Lo + t * (this->Hi - this->Lo);
}

int NumberControl::positionOf(double value) const
{
  double t = 0.0;
  if (this->Logarithmic)
  {
    const double from = std::max(this->Lo, 1.0);
    t = std::log(std::max(from, value) / from) / std::log(this->Hi / from);
  }
  else if (this->Hi > this->Lo)
  {
    t = (value - this->Lo) / (this->Hi - this->Lo);
  }
  return static_cast<int>(std::lround(kSteps * std::clamp(t, 0.0, 1.0)));
}

void NumberControl::setValue(double value)
{
  this->Value = value;
  const QSignalBlocker blockSlider(this->Slider);
  const QSignalBlocker blockBox(this->Box);
  this->Slider->setValue(this->positionOf(value));
  this->Box->setValue(value);
}

void NumberControl::set(double value)
{
  if (value == this->Value)
  {
    return;
  }
  this->setValue(value);
  emit valueChanged(value);
}

} // namespace viewer
} // namespace shadelab
