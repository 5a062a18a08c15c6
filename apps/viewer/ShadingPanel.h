#ifndef shadelab_viewer_ShadingPanel_h
#define shadelab_viewer_ShadingPanel_h
/**
 * @class   ShadingPanel
 * @brief   The lighting model, the shading frequency (flat, Gouraud, Phong),
 *          the split view flat | Gouraud | Phong, and the background.
 *
 * When the model is anisotropic and the mesh has no tangents, a line under
 * the model says so (ViewerDocument::tangentsProblem()) with a button that
 * computes them, enabled when the mesh has texture coordinates; the same
 * line goes out once as notice() when the model or mesh changes to that.
 */

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;

namespace shadelab
{
namespace viewer
{
class ColorButton;
class SceneView;
class ViewerDocument;

class ShadingPanel : public QWidget
{
  Q_OBJECT
public:
  ShadingPanel(ViewerDocument* document, SceneView* view, QWidget* parent = nullptr);

  QComboBox* modelBox() const { return this->Model; }
  QComboBox* frequencyBox() const { return this->Frequency; }
  QCheckBox* splitBox() const { return this->Split; }
  /// The line about missing tangents (hidden when there is nothing to say) and its button.
  QLabel* tangentsLabel() const { return this->Tangents; }
  QPushButton* tangentsButton() const { return this->ComputeTangents; }

signals:
  /// A one-line message for the status bar.
  void notice(const QString& message);
  void problem(const QString& message);

private:
  void showScene();
  void showTangents();

  ViewerDocument* Document;
  QComboBox* Model;
  QComboBox* Frequency;
  QCheckBox* Split;
  ColorButton* Background;
  QLabel* Tangents;
  QPushButton* ComputeTangents;
};

} // namespace viewer
} // namespace shadelab

#endif
