#ifndef shadelab_viewer_BrdfPanel_h
#define shadelab_viewer_BrdfPanel_h
/**
 * @class   BrdfPanel
 * @brief   The BRDF lobe at a point picked on the mesh: drawn on the mesh in
 *          the point's normal frame (slLobesOnMesh), and as slLobeImageRenderer's
 *          three-part picture (3D lobe, polar plot of the plane of incidence,
 *          albedo against incidence) for the scene's model, the material's
 *          numbers (shininess, roughness, ...) and the incidence angle of the
 *          chosen light at that point. The picture's frame has the tangent
 *          in the plane of incidence; the lobe on the mesh uses the mesh's
 *          own tangents (anisotropic models need them).
 */

#include <vtkType.h>

#include <QWidget>

class QLabel;
class QPushButton;
class QSpinBox;
class QTimer;

namespace shadelab
{
namespace viewer
{
class SceneView;
class ViewerDocument;

class BrdfPanel : public QWidget
{
  Q_OBJECT
public:
  BrdfPanel(ViewerDocument* document, SceneView* view, QWidget* parent = nullptr);

  QPushButton* pickButton() const { return this->Pick; }
  /// The light whose lobe is drawn: 0 to the scene's last light.
  QSpinBox* lightBox() const { return this->Light; }
  /// Shows the lobe at the mesh point nearest to (x, y, z).
  void showLobeAt(double x, double y, double z);
  /// The picked point (index into the view's meshWithNormals()), or -1.
  vtkIdType pickedPoint() const { return this->Point; }
  /// The incidence angle in degrees at the picked point (NaN if below the horizon).
  double incidenceDegrees() const { return this->Incidence; }
  /// What the panel says about the point: its incidence, the model and the numbers it reads.
  QLabel* infoLabel() const { return this->Info; }
  /// The three-part picture currently shown.
  QLabel* pictureLabel() const { return this->Picture; }

signals:
  void problem(const QString& message);

private:
  void update();

  ViewerDocument* Document;
  SceneView* View;
  QPushButton* Pick;
  QSpinBox* Light;
  QLabel* Info;
  QLabel* Picture;
  QTimer* Pending; ///< coalesces bursts of scene edits into one update()
  vtkIdType Point = -1;
  double Incidence = 0.0;
};

} // namespace viewer
} // namespace shadelab

#endif
