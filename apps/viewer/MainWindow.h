#ifndef shadelab_viewer_MainWindow_h
#define shadelab_viewer_MainWindow_h
/**
 * @class   MainWindow
 * @brief   shadelab-viewer's window: the SceneView in the middle, the
 *          shading, material, lights, normals, fields and BRDF panels docked
 *          at the side, and File actions to open meshes and scenes (menu,
 *          command line, or drag and drop), save scenes, and save
 *          screenshots as PNG or EXR through OpenImageIO.
 *
 * Errors (an unreadable mesh, an invalid scene, a failed write) are shown in
 * the status bar and a message box with the same one-line text the
 * command-line tools print; nothing already loaded is lost.
 */

#include <vtkSmartPointer.h>

#include <QMainWindow>

#include <functional>

class vtkImageData;

namespace shadelab
{
namespace viewer
{
class BrdfFilePanel;
class BrdfPanel;
class FieldsPanel;
class LightPanel;
class MaterialPanel;
class NormalsPanel;
class SceneView;
class ShadingPanel;
class ViewerDocument;

class MainWindow : public QMainWindow
{
  Q_OBJECT
public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  /// Opens a mesh, or a scene if @p path ends in .json. False on error
  /// (reported in the status bar and returned in @p error).
  bool openFile(const QString& path, QString* error = nullptr);
  bool saveScene(const QString& path, QString* error = nullptr);
  /// Writes the view as PNG, EXR or any format OpenImageIO writes.
  bool saveScreenshot(const QString& path, QString* error = nullptr);
  /// Writes the whole window, panels included, the same way.
  bool saveWindowScreenshot(const QString& path, QString* error = nullptr);
  /// Sets the size of the 3D view in pixels (the scene's imageSize to match `shadelab render`).
  void setViewSize(int width, int height);
  /// Brings the panel titled @p name (any case) to the front; false if there is none.
  bool raisePanel(const QString& name);
  /// The panels' titles, in the order of their tabs: the names raisePanel()
  /// and the --panel option take.
  static QStringList panelNames();
  /// When on (tests, scripts), errors only go to the status bar: no message box.
  void setQuiet(bool quiet) { this->Quiet = quiet; }

  ViewerDocument* document() const { return this->Document; }
  SceneView* view() const { return this->View; }
  ShadingPanel* shadingPanel() const { return this->Shading; }
  MaterialPanel* materialPanel() const { return this->Material; }
  LightPanel* lightPanel() const { return this->Lights; }
  NormalsPanel* normalsPanel() const { return this->Normals; }
  FieldsPanel* fieldsPanel() const { return this->Fields; }
  BrdfPanel* brdfPanel() const { return this->Brdf; }
  BrdfFilePanel* brdfFilePanel() const { return this->BrdfFileEditor; }

protected:
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

private:
  void buildMenus();
  /// Writes what @p capture returns to @p path (slImageWriter: atomic, the
  /// format by extension); a problem goes to the status bar and @p error.
  bool writeImage(const std::function<vtkSmartPointer<vtkImageData>()>& capture, const QString& path, QString* error);
  void showProblem(const QString& message);
  void updateTitle();

  ViewerDocument* Document;
  SceneView* View;
  ShadingPanel* Shading;
  MaterialPanel* Material;
  LightPanel* Lights;
  NormalsPanel* Normals;
  FieldsPanel* Fields;
  BrdfPanel* Brdf;
  BrdfFilePanel* BrdfFileEditor;
  bool Quiet = false;
};

} // namespace viewer
} // namespace shadelab

#endif
