#ifndef slSceneRenderer_h
#define slSceneRenderer_h
/**
 * @class   slSceneRenderer
 * @brief   Renders one mesh with an slScene offscreen and returns the image.
 *
 * slSceneRenderer builds a VTK pipeline (mapper, actor, renderer, offscreen
 * render window) configured by an slScene, renders one frame at the scene's
 * image size and captures it as an RGB vtkImageData. By default the renderer
 * draws through an slLightingPass, so the scene's lighting model, lights and
 * shading frequency are shown exactly; UseShadeLabLightingOff() shows VTK's
 * built-in lighting instead (see slScene's conversion notes for what it
 * lacks). It is what `shadelab render` and the image regression tests use.
 *
 * Rendering is deterministic: fixed window size, multisampling off, and the
 * camera fixed by the scene (or fitted to the mesh the same way each time).
 * If the mesh has no point normals and the scene's frequency is not flat,
 * slPolyDataNormals computes them (by default angle weighting, feature edges
 * over 30 degrees kept sharp, coincident points welded so that texture seams
 * do not show) so that Gouraud and Phong shading have normals to interpolate.
 *
 * Prepare() builds the renderer without a window, for applications that show
 * it in their own (shadelab-viewer's Qt widget): the same scene then gives
 * the same pixels there as Render() gives offscreen.
 *
 * @warning Debian's VTK renders through X11 only: an X server is needed
 * (run under xvfb-run). Render() fails cleanly when DISPLAY is not set.
 *
 * @sa slScene vtkWindowToImageFilter
 */

#include "ShadeLabRenderPassesModule.h"

#include <vtkObject.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class slLightingPass;
class slScene;
class vtkActor;
class vtkImageData;
class vtkPolyData;
class vtkRenderWindow;
class vtkRenderer;

class SHADELABRENDERPASSES_EXPORT slSceneRenderer : public vtkObject
{
public:
  static slSceneRenderer* New();
  vtkTypeMacro(slSceneRenderer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The scene (required) and the mesh to render (required).
  void SetScene(slScene* scene);
  slScene* GetScene();
  void SetMesh(vtkPolyData* mesh);
  vtkPolyData* GetMesh();
  ///@}

  ///@{
  /// Extra surfaces drawn with the mesh (lobes, glyphs), lit like it, with
  /// the RGB colour (0..1) standing in for the base colour.
  void AddOverlay(vtkPolyData* overlay, double r, double g, double b);
  void RemoveAllOverlays();
  ///@}

  ///@{
  /// Image size in pixels; 0 means "the scene's imageSize". Other values
  /// are clamped to the scene format's range (shadelab::kMinImageSize to
  /// kMaxImageSize, SceneLimits.h).
  void SetWidth(int width);
  vtkGetMacro(Width, int);
  void SetHeight(int height);
  vtkGetMacro(Height, int);
  ///@}

  ///@{
  /// Draw through an slLightingPass (default) or with VTK's own lighting.
  vtkSetMacro(UseShadeLabLighting, bool);
  vtkGetMacro(UseShadeLabLighting, bool);
  vtkBooleanMacro(UseShadeLabLighting, bool);
  ///@}

  ///@{
  /// How normals are computed when the mesh has none (see slPolyDataNormals):
  /// weighting (an slPolyDataNormals::WeightingType, default ANGLE), feature
  /// splitting (default on) at FeatureAngle degrees (default 30). With
  /// ReplaceNormals on (default off) normals the mesh has are recomputed too,
  /// at every shading frequency.
  vtkSetClampMacro(NormalsWeighting, int, 0, 3);
  vtkGetMacro(NormalsWeighting, int);
  vtkSetMacro(Splitting, bool);
  vtkGetMacro(Splitting, bool);
  vtkBooleanMacro(Splitting, bool);
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  vtkSetMacro(ReplaceNormals, bool);
  vtkGetMacro(ReplaceNormals, bool);
  vtkBooleanMacro(ReplaceNormals, bool);
  ///@}

  /// The lighting pass used by Render(), to set component views before it.
  slLightingPass* GetLightingPass();

  /// Builds the renderer (actor, overlays, lights, camera, lighting pass)
  /// without a window; GetRenderer() then returns it, ready to be added to
  /// any render window of the scene's size. False, after vtkErrorMacro, on
  /// failure.
  bool Prepare();

  /// Prepare(), then renders one frame offscreen and captures it. False,
  /// after vtkErrorMacro, on failure, among them a scene's .brdf file that
  /// cannot be read or whose GLSL does not compile (the pass's
  /// GetBrdfError(), one line); GetImage() is then null.
  bool Render();

  /// The mesh as drawn by the last Prepare(): the input, or a copy with the
  /// normals computed for it.
  vtkPolyData* GetRenderedMesh();

  /// The last rendered frame: RGB, unsigned char, row 0 at the bottom.
  vtkImageData* GetImage();

  /// The renderer and window of the last Render(), for further use.
  vtkRenderer* GetRenderer();
  vtkRenderWindow* GetRenderWindow();
  vtkActor* GetActor();

  /// True if an X display is available for rendering (DISPLAY is set).
  static bool HasDisplay();

protected:
  slSceneRenderer();
  ~slSceneRenderer() override;

private:
  slSceneRenderer(const slSceneRenderer&) = delete;
  void operator=(const slSceneRenderer&) = delete;

  vtkSmartPointer<slScene> Scene;
  vtkSmartPointer<vtkPolyData> Mesh;
  vtkSmartPointer<vtkPolyData> RenderedMesh;
  struct Overlay
  {
    vtkSmartPointer<vtkPolyData> data;
    double rgb[3];
  };
  std::vector<Overlay> Overlays;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkActor> Actor;
  vtkSmartPointer<vtkImageData> Image;
  vtkSmartPointer<slLightingPass> LightingPass;
  bool UseShadeLabLighting = true;
  int NormalsWeighting = 2;
  bool Splitting = true;
  double FeatureAngle = 30.0;
  bool ReplaceNormals = false;
  int Width = 0;
  int Height = 0;
};

#endif
