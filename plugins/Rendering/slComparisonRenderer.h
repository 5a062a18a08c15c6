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
 * |panel A - panel B| times an amplification factor.
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
  /// Returns false (and adds nothing) for an unknown name.
  bool AddPanel(const char* label, const char* model, const char* frequency);
  void RemoveAllPanels();
  int GetNumberOfPanels() const { return static_cast<int>(this->Panels.size()); }

  /// Appends a panel showing |panel a - panel b| x amplification (a, b
  /// 0-based). A negative @p a removes it.
  void SetDifference(int a, int b, double amplification);

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
  void FillDifference(vtkImageData* plain, vtkImageData* image) const;

  vtkSmartPointer<slScene> Scene;
  vtkSmartPointer<vtkPolyData> Mesh;
  std::vector<Panel> Panels;
  int DifferenceA = -1;
  int DifferenceB = -1;
  double Amplification = 4.0;
};

#endif
