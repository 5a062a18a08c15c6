#ifndef shadelab_viewer_LightPanel_h
#define shadelab_viewer_LightPanel_h
/**
 * @class   LightPanel
 * @brief   Adds, removes and edits the scene's lights: the type, and one row
 *          per key of a light in a scene file (shadelab::lightKeys(), the
 *          rows of SHADELAB_LIGHT_KEYS): name, space, intensity, ambient /
 *          diffuse / specular colours, position, direction, attenuation
 *          c1 + c2 d + c3 d^2, spot cutoff, exponent and smooth edge.
 *
 * Each row is built from its key: the key's name as the label, what it means
 * as the tooltip, the key's range as the range of its spin boxes, and it is
 * live only for the light types that take the key. An edit writes that one
 * key of the selected light and nothing else, so values the panel shows
 * rounded are never written back rounded; the one exception is the space:
 * switching between world and camera space converts the position and
 * direction with the view's camera (lightInSpace()), so the light stays
 * where it is in the view. Colours take the key's range, above 1 too
 * (ColorButton). Position and direction follow the light widgets in the
 * view while they are dragged. Every edit reaches the view as uniforms
 * (LightsChange); adding or removing a light, or changing its type, selects
 * another shader variant. No more lights can be added than the lighting
 * pass draws.
 */

#include <QString>
#include <QWidget>

#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QListWidget;
class QPushButton;
class QCheckBox;
class QFormLayout;

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
  QPushButton* addButton() const { return this->Add; }
  QComboBox* typeBox() const { return this->Type; }
  /// Adds a light of type @p typeName ("directional", "point", "spot", "ambient").
  void addLight(const QString& typeName);
  void removeSelectedLight();

  /// The row of light key @p key ("intensity", "position", ...), or null.
  QWidget* editor(const QString& key) const;
  /// The spin box of a number key ("intensity", "cutoff"), or null.
  QDoubleSpinBox* numberBox(const QString& key) const;
  /// Component @p i of a three-number key ("position", "direction", "attenuation"), or null.
  QDoubleSpinBox* componentBox(const QString& key, int i) const;
  /// The colour of a colour key ("ambient", "diffuse", "specular"), or null.
  ColorButton* colourButton(const QString& key) const;

private:
  struct Row
  {
    size_t key = 0; ///< index in shadelab::lightKeys()
    QWidget* editor = nullptr;
    QDoubleSpinBox* number = nullptr;
    QDoubleSpinBox* components[3] = { nullptr, nullptr, nullptr };
    ColorButton* colour = nullptr;
    QLineEdit* text = nullptr;
    QComboBox* space = nullptr;
  };

  void addRow(size_t key);
  /// The row of light key @p key, or null.
  const Row* rowOf(const QString& key) const;
  void showScene();
  void showLight(int index);
  /// Writes row @p row's value into the selected light.
  void editKey(size_t row);
  void editType();

  ViewerDocument* Document;
  SceneView* View; ///< its camera converts a light between world and camera space
  QListWidget* List;
  QPushButton* Add;
  QPushButton* Remove;
  QCheckBox* ShowWidgets;
  QWidget* Editor;
  QFormLayout* Form;
  QComboBox* Type;
  std::vector<Row> Rows;
  bool Showing = false; ///< filling the editor: its signals are not edits
};

} // namespace viewer
} // namespace shadelab

#endif
