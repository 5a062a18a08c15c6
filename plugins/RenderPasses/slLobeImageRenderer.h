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

#include <vtkObject.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkImageData;

class SHADELABRENDERPASSES_EXPORT slLobeImageRenderer : public vtkObject
{
public:
  static slLobeImageRenderer* New();
  vtkTypeMacro(slLobeImageRenderer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Adds a model by its scene-file name; false for an unknown name.
  bool AddModel(const char* name);
  void RemoveAllModels();

  ///@{
  /// Lobe parameters, as slBRDFLobeSource's.
  vtkSetClampMacro(Shininess, double, 0.0, 1.0e4);
  vtkGetMacro(Shininess, double);
  vtkSetClampMacro(IncidenceAngle, double, 0.0, 90.0);
  vtkGetMacro(IncidenceAngle, double);
  vtkSetClampMacro(DiffuseWeight, double, 0.0, 1.0e3);
  vtkGetMacro(DiffuseWeight, double);
  vtkSetClampMacro(SpecularWeight, double, 0.0, 1.0e3);
  vtkGetMacro(SpecularWeight, double);
  vtkSetMacro(MultiplyByCosine, bool);
  vtkGetMacro(MultiplyByCosine, bool);
  ///@}

  ///@{
  /// Size of each of the three panels in pixels.
  vtkSetClampMacro(PanelWidth, int, 64, 4096);
  vtkGetMacro(PanelWidth, int);
  vtkSetClampMacro(PanelHeight, int, 64, 4096);
  vtkGetMacro(PanelHeight, int);
  ///@}

  /// Renders the three panels. False, with GetErrorMessage(), on failure.
  bool Render();

  /// The image (RGB, unsigned char).
  vtkImageData* GetImage();

  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

protected:
  slLobeImageRenderer();
  ~slLobeImageRenderer() override;

private:
  slLobeImageRenderer(const slLobeImageRenderer&) = delete;
  void operator=(const slLobeImageRenderer&) = delete;

  std::vector<int> Models;
  double Shininess = 20.0;
  double IncidenceAngle = 45.0;
  double DiffuseWeight = 0.0;
  double SpecularWeight = 1.0;
  bool MultiplyByCosine = false;
  int PanelWidth = 400;
  int PanelHeight = 360;
  vtkSmartPointer<vtkImageData> Image;
  std::string ErrorMessage;
};

#endif
