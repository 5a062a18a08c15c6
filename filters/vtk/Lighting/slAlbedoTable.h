#ifndef slAlbedoTable_h
#define slAlbedoTable_h
/**
 * @class   slAlbedoTable
 * @brief   Directional albedo against incidence angle for every lighting
 *          model (or those enabled), as a vtkTable: column
 *          "IncidenceDegrees" and one column per model ("lambert",
 *          "phong", ..., "ashikhmin-shirley").
 *
 * a(theta_i) = integral of f_r(w_i, w_o) cos(theta_o) dw_o over the
 * hemisphere (shadelab::directionalAlbedo(): adaptive Gauss-Kronrod in the
 * lobe's own frame, within 1e-4 of an independent quadrature at every angle
 * up to 89.9 degrees, shininess 0 to 10^4 and every roughness from the
 * formulas' floor 0.01 to 1: tests/core/AlbedoAccuracyTest.cxx), with f_r
 * from slBRDF() of slLighting.glsl: k_d = 1 for the models without a
 * specular term (Lambert, Oren-Nayar), k_s = 1 and k_d = 0 for the others
 * (their specular lobe alone), and the material's numbers
 * (SetMaterialParameter()). It shows how much energy the lecture models gain
 * or lose (lecture Lambert reflects pi, lecture Phong grows toward grazing
 * incidence), that the normalised models stay <= 1, and what single
 * scattering loses at high roughness (Cook-Torrance GGX with F = 1 reflects
 * 1 - ln 2 at roughness 1 and normal incidence).
 *
 * @warning Two normalised models exceed 1 near grazing incidence, as
 * published: Oren-Nayar's qualitative model (by under 1 %) and Ward's
 * 1 / sqrt(cos_i cos_o) normalisation (up to about 1.8 at 89.9 degrees).
 *
 * @warning The last angle is MaximumIncidence (89 degrees unless set, at most
 * 89.9), not 90: at grazing incidence f_r cos(theta_i) -> 0 while the lecture
 * models' f_r diverges.
 *
 * @sa slBRDFLobeSource
 */

#include "ShadeLabLightingModule.h"

#include <vtkTableAlgorithm.h>

#include <memory>
#include <vector>

#ifndef __VTK_WRAP__
namespace shadelab
{
struct SceneMaterial;
}
#endif

class SHADELABLIGHTING_EXPORT slAlbedoTable : public vtkTableAlgorithm
{
public:
  static slAlbedoTable* New();
  vtkTypeMacro(slAlbedoTable, vtkTableAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

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
  /// Shininess n of the Phong and Blinn-Phong models:
  /// SetMaterialParameter("shininess", n).
  void SetShininess(double shininess);
  double GetShininess();
  ///@}

  ///@{
  /// Number of incidence angles, evenly spaced from 0 to MaximumIncidence
  /// degrees (default 10).
  vtkSetClampMacro(NumberOfAngles, int, 2, 1000);
  vtkGetMacro(NumberOfAngles, int);
  ///@}

  ///@{
  /// The last incidence angle in degrees (default 89, at most 89.9).
  vtkSetClampMacro(MaximumIncidence, double, 0.0, 89.9);
  vtkGetMacro(MaximumIncidence, double);
  ///@}

  ///@{
  /// Which models get a column, by SL_MODEL_* value (isLightingModel()) or
  /// by scene-file name ("ward"): every model by default. A disabled model
  /// is not computed (the albedo of all eleven at 10 angles takes about
  /// 0.2 s on one thread; a viewer that draws one needs one). Columns stay
  /// in model order. An unknown model is an error (vtkErrorMacro): false,
  /// nothing changes, and GetModelEnabled() returns false.
  bool SetModelEnabled(int model, bool enabled);
  bool SetModelEnabled(const char* name, bool enabled);
  bool GetModelEnabled(int model);
  void EnableAllModels();
  void DisableAllModels();
  ///@}

protected:
  slAlbedoTable();
  ~slAlbedoTable() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slAlbedoTable(const slAlbedoTable&) = delete;
  void operator=(const slAlbedoTable&) = delete;

  std::unique_ptr<shadelab::SceneMaterial> Material;
  int NumberOfAngles = 10;
  double MaximumIncidence = 89.0;
  std::vector<bool> ModelEnabled;
};

#endif
