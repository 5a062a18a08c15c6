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
 * plane, light on the -x side so the mirror lobe leans toward +x; the slice
 * is in the x-z plane at every angle, 0 included), with the
 * surface tangent along +x (anisotropic models: roughnessX along x,
 * roughnessY along y). The point array "BRDF" holds r. f_r is slBRDF() of
 * slLighting.glsl with k_d = DiffuseWeight and k_s = SpecularWeight (grey)
 * and the material's numbers (SetMaterialParameter()).
 *
 * f_r may instead come from elsewhere, per point (a BRDF Explorer `.brdf`
 * file, whose GLSL only the GPU runs: slBRDFFileEvaluator):
 * ComputeOutgoingDirections() lists the directions of both outputs' points,
 * SetBRDFValues() takes f_r at them, and the geometry is the same.
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
#include "slMaterialNumberAccessors.h" // the plain methods

#include <vtkPolyDataAlgorithm.h>
#include <vtkSmartPointer.h>

class vtkFloatArray;

#include <memory>
#include <string>

#ifndef __VTK_WRAP__
namespace shadelab
{
struct SceneMaterial;
}
#endif

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
  /// By scene-file name (those of slScene::SetModelName()); an unknown
  /// name is an error (vtkErrorMacro): false, and the model as it was.
  bool SetModelName(const char* name);
  std::string GetModelName() const;
  ///@}

  ///@{
  /// A number of the material by its scene-file key: "shininess",
  /// "roughness", "roughnessX", "roughnessY", "ior" (the number rows of
  /// SHADELAB_MATERIAL_PARAMETERS in shadelab/LightingTables.h), clamped to
  /// the scene format's range for it. Defaults are the table's, except
  /// shininess (20). An unknown key is an error (vtkErrorMacro): false, and
  /// the getter returns NaN.
  bool SetMaterialParameter(const char* key, double value);
  double GetMaterialParameter(const char* key);
  ///@}

  ///@{
  /// Shininess n: SetMaterialParameter("shininess", n); and the other
  /// numbers as plain methods for ParaView (SetRoughness(a):
  /// SetMaterialParameter("roughness", a); RoughnessX, RoughnessY, Ior).
  void SetShininess(double shininess);
  double GetShininess();
  slMaterialNumberForwardersMacro()
  ///@}

  ///@{
  /// k_d and k_s (grey). A negative weight (the default, -1) is the
  /// model's unit weight, as in slAlbedoTable: k_d = 1 for lambert,
  /// lambert-normalized and oren-nayar, which have no specular term; k_s = 1
  /// and k_d = 0 for the others (the specular lobe alone).
  vtkSetClampMacro(DiffuseWeight, double, -1.0, 1.0e3);
  vtkGetMacro(DiffuseWeight, double);
  vtkSetClampMacro(SpecularWeight, double, -1.0, 1.0e3);
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

  /// The unit direction toward the light for IncidenceAngle (in the x-z
  /// plane, on the -x side), with N = +z.
  void GetDirectionToLight(double toLight[3]);

  /// Fills @p surface and @p slice (3 components) with the outgoing unit
  /// directions of output 0's and output 1's points, in point order, for
  /// the current settings.
  void ComputeOutgoingDirections(vtkFloatArray* surface, vtkFloatArray* slice);

  ///@{
  /// f_r (RGB, 3 components) at the directions of
  /// ComputeOutgoingDirections(), used instead of the lighting model (whose
  /// settings then matter only for the directions); nullptr (the default)
  /// returns to the model. Arrays of another size than the directions are
  /// an error at the next update (empty outputs).
  void SetBRDFValues(vtkFloatArray* surface, vtkFloatArray* slice);
  vtkFloatArray* GetSurfaceBRDFValues();
  vtkFloatArray* GetSliceBRDFValues();
  ///@}

protected:
  slBRDFLobeSource();
  ~slBRDFLobeSource() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slBRDFLobeSource(const slBRDFLobeSource&) = delete;
  void operator=(const slBRDFLobeSource&) = delete;

  int Model = 1;
  std::unique_ptr<shadelab::SceneMaterial> Material;
  double DiffuseWeight = -1.0;
  double SpecularWeight = -1.0;
  double IncidenceAngle = 45.0;
  bool MultiplyByCosine = false;
  int ThetaResolution = 32;
  int PhiResolution = 64;
  vtkSmartPointer<vtkFloatArray> SurfaceBRDFValues;
  vtkSmartPointer<vtkFloatArray> SliceBRDFValues;
};

#endif
