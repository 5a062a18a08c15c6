#ifndef shadelab_viewer_FieldsPanel_h
#define shadelab_viewer_FieldsPanel_h
/**
 * @class   FieldsPanel
 * @brief   Shows a lighting field on the mesh, colour-mapped with a scalar
 *          bar: N.L (clamped or raw), the diffuse, specular or total
 *          radiance, and the Monte Carlo reference with its error against
 *          the discrete lights and its standard error.
 *
 * Fields come from slCosineField, slRadianceFilter and slRadianceReference on
 * the view's mesh and normals, with the view's camera as the eye, and are
 * recomputed when the scene, the normals or the mesh's tangents change. The
 * reference runs as a ReferenceJob: a progress bar, a cancel button, and a
 * note when the scene has changed since it was computed (or while it was).
 * A reference still running when another mesh is opened is dropped.
 */

#include <vtkSmartPointer.h>

#include <QWidget>

class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class vtkPolyData;

namespace shadelab
{
namespace viewer
{
class ReferenceJob;
class SceneView;
class ViewerDocument;

class FieldsPanel : public QWidget
{
  Q_OBJECT
public:
  FieldsPanel(ViewerDocument* document, SceneView* view, QWidget* parent = nullptr);
  ~FieldsPanel() override;

  /// The field chooser; index 0 is "none" (the lit view).
  QComboBox* fieldBox() const { return this->Field; }
  QSpinBox* samplesBox() const { return this->Samples; }
  QPushButton* computeButton() const { return this->Compute; }
  QPushButton* cancelButton() const { return this->Cancel; }
  QProgressBar* progressBar() const { return this->Progress; }
  /// The light whose N.L is shown: 0 to the scene's last light.
  QSpinBox* lightBox() const { return this->Light; }
  /// The reference's state: computing, done, stale, discarded.
  QLabel* statusLabel() const { return this->Status; }
  ReferenceJob* job() const { return this->Job; }
  /// The last reference output, or null.
  vtkPolyData* reference() const;

signals:
  void problem(const QString& message);

private:
  void showField();
  void showLightCount();
  /// The scene, normals or tangents changed: a shown field is recomputed, a
  /// reference (computed or being computed) is stale.
  void lightingChanged();
  void startReference();
  void referenceFinished(const QString& error);

  ViewerDocument* Document;
  SceneView* View;
  QComboBox* Field;
  QSpinBox* Light;
  QSpinBox* Samples;
  QComboBox* Strategy;
  QLineEdit* Environment;
  QPushButton* Compute;
  QPushButton* Cancel;
  QProgressBar* Progress;
  QLabel* Status;
  ReferenceJob* Job;
  vtkSmartPointer<vtkPolyData> Reference;
  bool ReferenceStale = false;
  bool ChangedWhileRunning = false; ///< the running job's result is stale
  int MeshGeneration = 0;           ///< counts the meshes opened
  int JobMeshGeneration = 0;        ///< MeshGeneration when the job started
};

} // namespace viewer
} // namespace shadelab

#endif
