#ifndef shadelab_viewer_ColorButton_h
#define shadelab_viewer_ColorButton_h
/**
 * @class   ColorButton
 * @brief   A linear RGB coefficient, each component in [lo, hi] (a scene
 *          key's range), edited as a swatch (a colour dialog that updates
 *          live), a brightness slider and a brightness spin box.
 *
 * The brightness is the largest component; setting it scales the colour and
 * keeps the hue: this is how k_d = (0.72, 0.72, 0.72) becomes (0.36, 0.36,
 * 0.36) in one drag. The slider covers [lo, 1], where reflectances and most
 * light colours lie; the spin box shows the brightness to three decimals and
 * takes the whole range, so a light colour of 2 2 2 is shown as 2 and kept,
 * and 5 can be typed. The swatch shows the hue (the colour divided by its
 * brightness when that is above 1) and its tooltip the exact components;
 * a colour picked in the dialog keeps a brightness above 1. Values are
 * linear, as in scene files; a value is only ever written by an edit of
 * this control, never because it was shown.
 */

#include <glm/glm.hpp>

#include <QWidget>

class QDoubleSpinBox;
class QPushButton;
class QSlider;

namespace shadelab
{
namespace viewer
{

class ColorButton : public QWidget
{
  Q_OBJECT
public:
  /// Components in [@p lo, @p hi], the range of the colour's scene key.
  ColorButton(double lo, double hi, QWidget* parent = nullptr);
  /// Components in [0, 1].
  explicit ColorButton(QWidget* parent = nullptr);

  glm::vec3 value() const { return this->Value; }
  /// Shows @p value without emitting valueChanged.
  void setValue(const glm::vec3& value);
  /// The brightness slider (0..1000 for lo..min(hi, 1)), for tests and shortcuts.
  QSlider* slider() const { return this->Brightness; }
  /// The brightness spin box, over [lo, hi].
  QDoubleSpinBox* spinBox() const { return this->Box; }

signals:
  void valueChanged(const glm::vec3& value);

private:
  void pickColour();
  void setBrightness(double brightness);
  void show(const glm::vec3& value);

  double Lo, SliderHi;
  glm::vec3 Value{ 0.0f };
  QPushButton* Swatch;
  QSlider* Brightness;
  QDoubleSpinBox* Box;
};

} // namespace viewer
} // namespace shadelab

#endif
