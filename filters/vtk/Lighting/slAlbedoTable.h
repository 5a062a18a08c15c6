#ifndef slAlbedoTable_h
#define slAlbedoTable_h
/**
 * @class   slAlbedoTable
 * @brief   Directional albedo against incidence angle for every lighting
 *          model, as a vtkTable: column "IncidenceDegrees" and one column
 *          per model ("lambert", "phong", ..., "blinn-phong-normalized").
 *
 * a(theta_i) = integral of f_r(w_i, w_o) cos(theta_o) dw_o over the
 * hemisphere (shadelab::directionalAlbedo(): adaptive Gauss-Kronrod in the
 * lobe's own frame, within 1e-4 of an independent quadrature at every angle
 * up to 89.9 degrees and shininess 0 to 10^4), with f_r from
 * slBRDF() of slLighting.glsl: k_d = 1 for the Lambert models, k_s = 1 and
 * k_d = 0 for the Phong and Blinn-Phong models (their specular lobe alone).
 * It shows how much energy the lecture models gain or lose (lecture Lambert
 * reflects pi, lecture Phong grows toward grazing incidence) and that the
 * normalised models stay <= 1.
 *
 * @warning The last angle is MaximumIncidence (89 degrees unless set, at most
 * 89.9), not 90: at grazing incidence f_r cos(theta_i) -> 0 while the lecture
 * models' f_r diverges.
 *
 * @sa slBRDFLobeSource
 */

#include "ShadeLabLightingModule.h"

#include <vtkTableAlgorithm.h>

class SHADELABLIGHTING_EXPORT slAlbedoTable : public vtkTableAlgorithm
{
public:
  static slAlbedoTable* New();
  vtkTypeMacro(slAlbedoTable, vtkTableAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Shininess n of the specular models (default 20).
  vtkSetClampMacro(Shininess, double, 0.0, 1.0e4);
  vtkGetMacro(Shininess, double);
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

protected:
  slAlbedoTable();
  ~slAlbedoTable() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slAlbedoTable(const slAlbedoTable&) = delete;
  void operator=(const slAlbedoTable&) = delete;

  double Shininess = 20.0;
  int NumberOfAngles = 10;
  double MaximumIncidence = 89.0;
};

#endif
