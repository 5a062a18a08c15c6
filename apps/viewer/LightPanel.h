#ifndef shadelab_viewer_LightPanel_h
#define shadelab_viewer_LightPanel_h
/**
 * @class   LightPanel
 * @brief   Adds, removes and edits the scene's lights: type, space (world or
 *          camera), ambient / diffuse / specular colours, intensity,
 *          attenuation c1 + c2 d + c3 d^2, spot cutoff, exponent and smooth
 *          edge, position and direction.
 *
 * Position and direction follow the light widgets in the view while they are
 * dragged. Every edit reaches the view as uniforms (LightsChange); adding or
 * removing a light, or changing its type, selects another shader variant.
 */

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace shadelab
{
namespace viewer
{
class ColorButton;
class SceneView;
class ViewerDocument;

class LightPanel : public QWidget
{
  Q_OBJECT
public:
  LightPanel(ViewerDocument* document, SceneView* view, QWidget* parent = nullptr);

  QListWidget* list() const { return this->List; }
  /// Adds a light of type @p typeName ("directional", "point", "spot", "ambient").
  void addLight(const QString& typeName);
  void removeSelectedLight();

private:
  void showScene();
  void showLight(int index);
  void editLight();
  QDoubleSpinBox* spinBox(double minimum, double maximum, int decimals);

  ViewerDocument* Document;
  QListWidget* List;
  QPushButton* Add;
  QPushButton* Remove;
  QCheckBox* ShowWidgets;
  QWidget* Editor;
  QLineEdit* Name;
  QComboBox* Type;
  QComboBox* Space;
  ColorButton* Colours[3]; ///< ambient, diffuse, specular
  QDoubleSpinBox* Intensity;
  QDoubleSpinBox* Attenuation[3];
  QDoubleSpinBox* Cutoff;
  QDoubleSpinBox* Exponent;
  QDoubleSpinBox* Edge;
  QDoubleSpinBox* Position[3];
  QDoubleSpinBox* Direction[3];
  bool Showing = false; ///< filling the editor: its signals are not edits
};

} // namespace viewer
} // namespace shadelab

#endif
