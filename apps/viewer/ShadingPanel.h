#ifndef shadelab_viewer_ShadingPanel_h
#define shadelab_viewer_ShadingPanel_h
/**
 * @class   ShadingPanel
 * @brief   The lighting model, the shading frequency (flat, Gouraud, Phong),
 *          the split view flat | Gouraud | Phong, and the background.
 */

#include <QWidget>

class QCheckBox;
class QComboBox;

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

private:
  void showScene();

  ViewerDocument* Document;
  QComboBox* Model;
  QComboBox* Frequency;
  QCheckBox* Split;
  ColorButton* Background;
};

} // namespace viewer
} // namespace shadelab

#endif
