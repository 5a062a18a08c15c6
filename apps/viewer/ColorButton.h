#ifndef shadelab_viewer_ColorButton_h
#define shadelab_viewer_ColorButton_h
/**
 * @class   ColorButton
 * @brief   A linear RGB coefficient in [0, 1]^3 edited as a swatch (a colour
 *          dialog that updates live) plus a brightness slider that scales it.
 *
 * The slider shows and sets the largest component, keeping the hue: this is
 * how k_d = (0.72, 0.72, 0.72) becomes (0.36, 0.36, 0.36) in one drag. Values
 * are linear, as in scene files; the swatch shows them as they are.
 */

#include <glm/glm.hpp>

#include <QWidget>

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
  explicit ColorButton(QWidget* parent = nullptr);

  glm::vec3 value() const { return this->Value; }
  /// Shows @p value without emitting valueChanged.
  void setValue(const glm::vec3& value);
  /// The brightness slider (0..1000 for 0..1), for tests and shortcuts.
  QSlider* slider() const { return this->Brightness; }

signals:
  void valueChanged(const glm::vec3& value);

private:
  void pickColour();
  void setBrightness(int sliderValue);
  void show(const glm::vec3& value);

  glm::vec3 Value{ 0.0f };
  QPushButton* Swatch;
  QSlider* Brightness;
};

} // namespace viewer
} // namespace shadelab

#endif
