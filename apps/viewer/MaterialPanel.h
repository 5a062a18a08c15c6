#ifndef shadelab_viewer_MaterialPanel_h
#define shadelab_viewer_MaterialPanel_h
/**
 * @class   MaterialPanel
 * @brief   Edits the scene's material live: k_a, k_d, k_s, k_e (ColorButton
 *          each) and the shininess n on a logarithmic slider from 1 to 4096.
 *
 * Every change goes to the document at once as a MaterialChange, which the
 * view turns into uniforms: dragging a slider re-renders without rebuilding.
 */

#include <QWidget>

class QDoubleSpinBox;
class QSlider;

namespace shadelab
{
namespace viewer
{
class ColorButton;
class ViewerDocument;

class MaterialPanel : public QWidget
{
  Q_OBJECT
public:
  explicit MaterialPanel(ViewerDocument* document, QWidget* parent = nullptr);

  /// The shininess slider: position s in 0..1000 means n = 4096^(s/1000).
  QSlider* shininessSlider() const { return this->ShininessSlider; }
  static double shininessAt(int sliderValue);
  static int sliderAt(double shininess);

private:
  void showScene();
  void setShininess(double shininess);

  ViewerDocument* Document;
  ColorButton* Coefficients[4]; ///< ambient, diffuse, specular, emission
  QSlider* ShininessSlider;
  QDoubleSpinBox* ShininessBox;
};

} // namespace viewer
} // namespace shadelab

#endif
