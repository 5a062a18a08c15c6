#ifndef slFieldImageRenderer_h
#define slFieldImageRenderer_h
/**
 * @class   slFieldImageRenderer
 * @brief   Renders fields of a mesh (CosTheta, Diffuse, Radiance, RadianceError,
 *          ...) colour-mapped, with a scalar bar each and the scene's lights
 *          drawn as glyphs, in a grid of panels sharing one camera.
 *
 * Each field is a point (or, failing that, cell) array of the mesh. One
 * component is mapped as it is; three (RGB terms) are mapped through their
 * luminance 0.2126 R + 0.7152 G + 0.0722 B. A field whose range straddles 0
 * (CosThetaRaw, RadianceError) gets a diverging blue-white-red map symmetric
 * about 0; other fields a sequential map over their range. The surface is
 * drawn unlit, so the colours are the values. Point and spot lights are
 * drawn as spheres in their diffuse colour, directional lights as arrows
 * pointing along the light toward the mesh; ambient lights have no glyph.
 *
 * @warning Needs an X display, like every ShadeLab rendering (xvfb-run).
 *
 * @sa slComparisonRenderer slCosineField slRadianceFilter slRadianceReference
 */

#include "ShadeLabRenderPassesModule.h"
#include "slPanelRenderer.h"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class slScene;
class vtkImageData;
class vtkRenderer;
class vtkPolyData;

class SHADELABRENDERPASSES_EXPORT slFieldImageRenderer : public slPanelRenderer
{
public:
  static slFieldImageRenderer* New();
  vtkTypeMacro(slFieldImageRenderer, slPanelRenderer);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The mesh holding the fields, and the scene (camera and lights).
  void SetMesh(vtkPolyData* mesh);
  void SetScene(slScene* scene);
  ///@}

  /// Adds a panel showing the array @p arrayName.
  void AddField(const char* arrayName);
  void RemoveAllFields();

  ///@{
  /// Panels per row (the grid has as many rows as needed).
  vtkSetClampMacro(Columns, int, 1, 16);
  vtkGetMacro(Columns, int);
  ///@}

  bool Render() override;

#ifndef __VTK_WRAP__
  /// One panel on its own: a renderer showing the point (or cell) array
  /// @p arrayName of @p mesh colour-mapped as described above, with its
  /// scalar bar and title laid out for a @p panelWidth x @p panelHeight
  /// viewport; no camera or lights are set. Throws shadelab::Error if the
  /// mesh has no such array. Render() builds its grid from these; shadelab-viewer
  /// shows one in its fields panel.
  static vtkSmartPointer<vtkRenderer> NewFieldRenderer(
    vtkPolyData* mesh, const std::string& arrayName, int panelWidth, int panelHeight);
#endif

protected:
  slFieldImageRenderer();
  ~slFieldImageRenderer() override;

private:
  slFieldImageRenderer(const slFieldImageRenderer&) = delete;
  void operator=(const slFieldImageRenderer&) = delete;

  vtkSmartPointer<vtkPolyData> Mesh;
  vtkSmartPointer<slScene> Scene;
  std::vector<std::string> Fields;
  int Columns = 3;
};

#endif
