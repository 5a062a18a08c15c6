#ifndef shadelab_viewer_NormalsPanel_h
#define shadelab_viewer_NormalsPanel_h
/**
 * @class   NormalsPanel
 * @brief   How the view's normals are computed (slPolyDataNormals weighting:
 *          uniform, area, angle, Max; feature-angle splitting), whether the
 *          file's own normals are replaced, and normals shown as glyphs.
 */

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;

namespace shadelab
{
namespace viewer
{
class SceneView;
class ViewerDocument;

class NormalsPanel : public QWidget
{
  Q_OBJECT
public:
  NormalsPanel(ViewerDocument* document, SceneView* view, QWidget* parent = nullptr);

  QComboBox* weightingBox() const { return this->Weighting; }
  QCheckBox* glyphsBox() const { return this->Glyphs; }

private:
  void apply();

  ViewerDocument* Document;
  QComboBox* Weighting;
  QCheckBox* Splitting;
  QDoubleSpinBox* FeatureAngle;
  QCheckBox* Replace;
  QCheckBox* Glyphs;
};

} // namespace viewer
} // namespace shadelab

#endif
