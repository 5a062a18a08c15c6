#ifndef shadelab_viewer_ViewerDocument_h
#define shadelab_viewer_ViewerDocument_h
/**
 * @class   ViewerDocument
 * @brief   What shadelab-viewer shows: one mesh, one scene (lights, material,
 *          model, frequency, camera) and how normals are computed for it.
 *
 * Panels edit the scene through setScene() and the normals through
 * setNormals(); views listen to the signals. Loading and saving go through
 * slMeshReader and slScene, so the viewer accepts exactly what `shadelab
 * render` accepts, with the same one-line errors, and writes scene files
 * atomically. A failed load leaves the document as it was.
 *
 * @sa SceneView slScene slMeshReader
 */

#include "shadelab/Scene.h"
#include "slRenderNormals.h"

#include <vtkSmartPointer.h>

#include <QObject>
#include <QString>

class slScene;
class vtkCamera;
class vtkPolyData;

namespace shadelab
{
namespace viewer
{

/// What an edit touched, so that views redo only what depends on it.
enum Change
{
  MaterialChange = 1,  ///< k_a, k_d, k_s, k_e, shininess: uniforms only
  LightsChange = 2,    ///< lights: uniforms unless their number or types change
  ShadingChange = 4,   ///< model or frequency: a shader variant
  BackgroundChange = 8,
  CameraChange = 16,   ///< the scene's camera replaces the view's
  EveryChange = 31
};

/// How the viewer computes normals: as ShadeLab's renderers do, with the
/// same defaults as `shadelab render` (angle weighting, 30 degree splitting).
using NormalsSettings = slRenderNormalsOptions;

class ViewerDocument : public QObject
{
  Q_OBJECT
public:
  /// Starts with ShadeLab's default scene and no mesh.
  explicit ViewerDocument(QObject* parent = nullptr);
  ~ViewerDocument() override;

  /// Reads a mesh (OBJ, PLY, STL, VTP, VTK, OFF, glTF). False, with the
  /// reader's one-line @p error, if it cannot; the current mesh stays.
  bool openMesh(const QString& path, QString& error);
  /// Reads a JSON scene. False with @p error (file: key: problem) if invalid,
  /// or if it has more lights than the lighting pass draws.
  bool openScene(const QString& path, QString& error);
  /// Reads a BRDF Explorer .brdf file and makes it the scene's BRDF, its
  /// parameters at their defaults (a ShadingChange). False with the
  /// reader's one-line @p error (FILE:LINE: reason) if it cannot.
  bool openBrdf(const QString& path, QString& error);
  /// Writes the scene as JSON, all or nothing.
  bool saveScene(const QString& path, QString& error);

  /// The scene being shown, and its VTK-side wrapper (for renderers and filters).
  const Scene& scene() const;
  slScene* vtkScene() const;
  /// Replaces the scene; @p changes (Change flags) says what differs.
  void setScene(const Scene& scene, int changes);
  /// Records the view's camera in the scene without signalling (before a save).
  void recordCamera(vtkCamera* camera);

  /// The mesh as read (no normals added), or null; and where it came from.
  vtkPolyData* mesh() const;
  QString meshPath() const;
  QString scenePath() const;

  const NormalsSettings& normals() const { return this->Normals; }
  void setNormals(const NormalsSettings& settings);

  /// One line saying what the scene's model needs that the mesh lacks, or ""
  /// when nothing: an anisotropic model (modelNeedsTangents()) on a mesh
  /// without "Tangents" (slLitFilter::HasTangents()), which the render pass
  /// draws in a fixed frame around the normal. It says whether
  /// computeTangents() can help.
  QString tangentsProblem() const;
  /// Whether computeTangents() can run: there is a mesh and it has texture coordinates.
  bool canComputeTangents() const;
  /// Adds MikkTSpace-style tangents (slPolyDataTangents, from the texture
  /// coordinates) to the mesh, which keeps its own normals or none (the
  /// normals settings still decide them). False with the filter's one-line
  /// @p error if it cannot; the mesh stays.
  bool computeTangents(QString& error);

signals:
  void meshChanged();
  /// The mesh gained tangents (same geometry; mirror seams may split points).
  void tangentsChanged();
  void sceneChanged(int changes);
  void normalsChanged();

private:
  vtkSmartPointer<slScene> SceneObject;
  vtkSmartPointer<vtkPolyData> Mesh;
  QString MeshPath;
  QString ScenePath;
  NormalsSettings Normals;
};

} // namespace viewer
} // namespace shadelab

#endif
