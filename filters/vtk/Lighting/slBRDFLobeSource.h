#ifndef slBRDFLobeSource_h
#define slBRDFLobeSource_h
/**
 * @class   slBRDFLobeSource
 * @brief   The BRDF lobe r(w_o) = f_r(w_i, w_o) (optionally x cos theta_o)
 *          of a lighting model, as a surface (output 0) and as the polar
 *          slice in the plane of incidence (output 1).
 *
 * The surface is origin + r(w_o) w_o over the hemisphere around +z, for the
 * incident direction given by IncidenceAngle (degrees from +z, in the x-z
 * plane, light on the -x side so the mirror lobe leans toward +x). The point
 * array "BRDF" holds r. f_r is slBRDF() of slLighting.glsl with k_d =
 * DiffuseWeight and k_s = SpecularWeight (grey).
 *
 * @warning The lecture models (lambert, phong, blinn-phong) are not
 * energy-normalised: read as BRDFs their lobes can be much larger than the
 * normalised ones; lecture Phong's f_r = k_s max(0,R.V)^n / cos theta_i
 * grows without bound toward grazing incidence (slBRDF returns 0 below
 * cos theta_i = 1e-6).
 *
 * @sa slLobesOnMesh slAlbedoTable slRadianceFilter
 */

#include "ShadeLabLightingModule.h"

#include <vtkPolyDataAlgorithm.h>

class SHADELABLIGHTING_EXPORT slBRDFLobeSource : public vtkPolyDataAlgorithm
{
public:
  static slBRDFLobeSource* New();
  vtkTypeMacro(slBRDFLobeSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Lighting model, an SL_MODEL_* value (a row of shadelab/LightingTables.h:
  /// lambert, phong, blinn-phong, lambert-normalized, ...). Default: phong.
  /// Any other value is an error (vtkErrorMacro) and leaves the model as it was.
  void SetModel(int model);
  vtkGetMacro(Model, int);
  ///@}

  ///@{
  /// Shininess n (default 20), clamped to the scene format's range
  /// [0, kMaxShininess] (shadelab/SceneLimits.h).
  void SetShininess(double shininess);
  vtkGetMacro(Shininess, double);
  ///@}

  ///@{
  /// k_d and k_s (grey; defaults 0 and 1: the specular lobe alone).
  vtkSetClampMacro(DiffuseWeight, double, 0.0, 1.0e3);
  vtkGetMacro(DiffuseWeight, double);
  vtkSetClampMacro(SpecularWeight, double, 0.0, 1.0e3);
  vtkGetMacro(SpecularWeight, double);
  ///@}

  ///@{
  /// Angle of incidence theta_i in degrees from the normal (default 45).
  vtkSetClampMacro(IncidenceAngle, double, 0.0, 90.0);
  vtkGetMacro(IncidenceAngle, double);
  ///@}

  ///@{
  /// Multiply r by cos theta_o (the reflected radiance per unit irradiance). Off by default.
  vtkSetMacro(MultiplyByCosine, bool);
  vtkGetMacro(MultiplyByCosine, bool);
  vtkBooleanMacro(MultiplyByCosine, bool);
  ///@}

  ///@{
  /// Rings from the pole to the horizon and segments around it (defaults 32, 64).
  vtkSetClampMacro(ThetaResolution, int, 1, 1024);
  vtkGetMacro(ThetaResolution, int);
  vtkSetClampMacro(PhiResolution, int, 3, 2048);
  vtkGetMacro(PhiResolution, int);
  ///@}

  /// The polar slice (output port 1).
  vtkPolyData* GetSliceOutput() { return this->GetOutput(1); }

protected:
  slBRDFLobeSource();
  ~slBRDFLobeSource() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slBRDFLobeSource(const slBRDFLobeSource&) = delete;
  void operator=(const slBRDFLobeSource&) = delete;

  int Model = 1;
  double Shininess = 20.0;
  double DiffuseWeight = 0.0;
  double SpecularWeight = 1.0;
  double IncidenceAngle = 45.0;
  bool MultiplyByCosine = false;
  int ThetaResolution = 32;
  int PhiResolution = 64;
};

#endif
