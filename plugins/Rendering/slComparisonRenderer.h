#ifndef slComparisonRenderer_h
#define slComparisonRenderer_h
/**
 * @class   slComparisonRenderer
 * @brief   Renders one mesh side by side under several lighting models or
 *          shading frequencies, with linked cameras, labels and an optional
 *          amplified difference panel, into one image.
 *
 * Each panel is a viewport of one offscreen window with its own
 * slLightingPass; all panels share one vtkCamera (fitted or placed by the
 * scene), so they show exactly the same view. AddPanel() chooses each
 * panel's model and frequency; SetDifference() appends a panel showing
 * |panel A - panel B| times an amplification factor. The panels fill rows of
 * Columns panels each, top row first (one row when Columns is 0); cells of a
 * short last row show the scene's background. The whole composite must fit
 * slMaximumWindowSize (slOffscreen.h): Render() fails with one line, before
 * any work, for a larger one.
 *
 * @warning Needs an X display, like every ShadeLab rendering (xvfb-run).
 *
 * @sa slLightingPass slSceneRenderer
 */

#include "ShadeLabRenderPassesModule.h"
#include "slPanelRenderer.h"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class slScene;
class vtkImageData;
class vtkPolyData;

class SHADELABRENDERPASSES_EXPORT slComparisonRenderer : public slPanelRenderer
{
public:
  static slComparisonRenderer* New();
  vtkTypeMacro(slComparisonRenderer, slPanelRenderer);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The scene (lights, material, camera) and the mesh.
  void SetScene(slScene* scene);
  void SetMesh(vtkPolyData* mesh);
  ///@}

  /// Adds a panel with a model and frequency by their scene-file names.
  /// An unknown name is an error (vtkErrorMacro): false, and nothing added.
  bool AddPanel(const char* label, const char* model, const char* frequency);
  void RemoveAllPanels();
  int GetNumberOfPanels() const { return static_cast<int>(this->Panels.size()); }

  /// Appends a panel showing |panel a - panel b| x amplification (a, b
  /// 0-based). A negative @p a removes it.
  void SetDifference(int a, int b, double amplification);

  ///@{
  /// Panels per row (the difference panel counts as one); 0, the default:
  /// every panel in one row.
  vtkSetClampMacro(Columns, int, 0, 64);
  vtkGetMacro(Columns, int);
  ///@}

  /// The size of the composite image of @p cells panels (the difference
  /// panel counts as one) with the panel size and Columns set now. Render()
  /// refuses, before any work, a composite beyond slMaximumWindowSize
  /// (slOffscreen.h), the largest image that can be rendered.
  void GetCompositeSize(int cells, int& width, int& height) const;

  bool Render() override;

protected:
  slComparisonRenderer();
  ~slComparisonRenderer() override;

private:
  slComparisonRenderer(const slComparisonRenderer&) = delete;
  void operator=(const slComparisonRenderer&) = delete;

  struct Panel
  {
    std::string label;
    int model;
    int frequency;
  };
  /// The grid: @p cells panels in rows of columns() each.
  int columns(int cells) const;
  /// The lower-left pixel of cell @p index in the image (row 0 at the
  /// bottom) of a grid of @p cells.
  void cellOrigin(int index, int cells, int& x, int& y) const;
  void FillDifference(vtkImageData* plain, vtkImageData* image) const;

  vtkSmartPointer<slScene> Scene;
  vtkSmartPointer<vtkPolyData> Mesh;
  std::vector<Panel> Panels;
  int DifferenceA = -1;
  int DifferenceB = -1;
  double Amplification = 4.0;
  int Columns = 0;
};

#endif
