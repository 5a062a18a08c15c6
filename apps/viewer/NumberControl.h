#ifndef shadelab_viewer_NumberControl_h
#define shadelab_viewer_NumberControl_h
/**
 * @class   NumberControl
 * @brief   One number in a closed range [lo, hi] edited as a slider plus a
 *          spin box; the slider is logarithmic over ranges of more than three
 *          decades (shininess), linear otherwise (roughness, ior).
 *
 * A logarithmic slider runs from max(lo, 1) to hi (a Phong exponent below 1
 * is a degenerate lobe); the spin box takes the whole range.
 */

#include <QWidget>

class QDoubleSpinBox;
class QSlider;

namespace shadelab
{
namespace viewer
{

class NumberControl : public QWidget
{
  Q_OBJECT
public:
  NumberControl(double lo, double hi, QWidget* parent = nullptr);

  double value() const { return this->Value; }
  /// Shows @p value without emitting valueChanged.
  void setValue(double value);

  QSlider* slider() const { return this->Slider; }
  QDoubleSpinBox* spinBox() const { return this->Box; }
  bool logarithmic() const { return this->Logarithmic; }
  /// The value at slider position @p position (0..1000), and the position nearest to @p value.
  double valueAt(int position) const;
  int positionOf(double value) const;

signals:
  void valueChanged(double value);

private:
  void set(double value);

  double Lo, Hi;
  bool Logarithmic;
  double Value = 0.0;
  QSlider* Slider;
  QDoubleSpinBox* Box;
};

} // namespace viewer
} // namespace shadelab

#endif
