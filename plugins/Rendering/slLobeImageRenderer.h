#ifndef slLobeImageRenderer_h
#define slLobeImageRenderer_h
/**
 * @class   slLobeImageRenderer
 * @brief   One image of BRDF lobes in three parts: the 3D lobes, a polar
 *          plot of the plane of incidence, and directional albedo against
 *          the angle of incidence; several models overlaid in colours.
 *
 * The lobes come from slBRDFLobeSource (output 0 for the surface, output 1
 * for the polar slice), the albedo curves from slAlbedoTable, so every value
 * is the lighting core's. The 3D panel views the plane of incidence from the
 * side and draws the incident and mirror directions; the two plots are
 * vtkChartXY charts with a legend.
 *
 * @warning Needs an X display, like every ShadeLab rendering (xvfb-run).
 *
 * @sa slBRDFLobeSource slAlbedoTable slFieldImageRenderer
 */

#include "ShadeLabRenderPassesModule.h"
#include "slPanelRenderer.h"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class slBRDFLobeSource;
class vtkImageData;

class SHADELABRENDERPASSES_EXPORT slLobeImageRenderer : public slPanelRenderer
{
public:
  static slLobeImageRenderer* New();
  vtkTypeMacro(slLobeImageRenderer, slPanelRenderer);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Adds a model by its scene-file name; false for an unknown name.
  bool AddModel(const char* name);
  void RemoveAllModels();

  /// The lobe parameters (shininess, incidence angle, k_d, k_s, cosine
  /// factor) are set on this source; Render() draws it once per model.
  slBRDFLobeSource* GetLobeParameters();

  bool Render() override;

protected:
  slLobeImageRenderer();
  ~slLobeImageRenderer() override;

private:
  slLobeImageRenderer(const slLobeImageRenderer&) = delete;
  void operator=(const slLobeImageRenderer&) = delete;

  std::vector<int> Models;
  vtkSmartPointer<slBRDFLobeSource> LobeParameters;
};

#endif
