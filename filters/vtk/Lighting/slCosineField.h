#ifndef slCosineField_h
#define slCosineField_h
/**
 * @class   slCosineField
 * @brief   The cosine N̂·L̂ per point and per cell, for one light or for every
 *          light: arrays CosTheta (clamped to >= 0, the cosine law) and
 *          CosThetaRaw (unclamped: negative where the surface faces away
 *          from the light, i.e. shadows itself).
 *
 * Point values use the point normals; cell values use the cell normals
 * ("Normals" cell array) when present, otherwise each polygon's own normal
 * (Newell's method) and each triangle strip's area-weighted mean of its
 * triangles' normals, at the cell's vertex centroid. For point and spot
 * lights L̂ changes from point to point; for directional lights it is
 * constant. The spot cone and attenuation do not enter: this is the
 * geometric cosine only (see slRadianceFilter for what reaches the point).
 *
 * With LightIndex = -1 (default) every light gets its own arrays, suffixed
 * by the light's index: CosTheta_0, CosThetaRaw_0, CosTheta_1, ...; with
 * LightIndex = i only light i is evaluated and the arrays have no suffix.
 *
 * The values come from slCosTheta() and slDiffuseFactor() of
 * slLighting.glsl. Ambient lights have no direction: their cosine is 0.
 * Zero-length normals (allowed when ZeroNormalsAreErrors is off) and
 * degenerate cells give 0, never NaN.
 *
 * @warning The cosine is local: nothing casts shadows, so a point facing a
 * light behind another part of the mesh still gets its full N̂·L̂. Cell
 * values at the vertex centroid are not the average of the point values
 * for point and spot lights.
 *
 * @sa slLitFilter slRadianceFilter
 */

#include "ShadeLabLightingModule.h"
#include "slLitFilter.h"

class SHADELABLIGHTING_EXPORT slCosineField : public slLitFilter
{
public:
  static slCosineField* New();
  vtkTypeMacro(slCosineField, slLitFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The light to evaluate (index into the scene's lights), or -1 for all.
  vtkSetClampMacro(LightIndex, int, -1, VTK_INT_MAX);
  vtkGetMacro(LightIndex, int);
  ///@}

  ///@{
  /// Also compute cell arrays (default on).
  vtkSetMacro(ComputeCellArrays, bool);
  vtkGetMacro(ComputeCellArrays, bool);
  vtkBooleanMacro(ComputeCellArrays, bool);
  ///@}

protected:
  slCosineField();
  ~slCosineField() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slCosineField(const slCosineField&) = delete;
  void operator=(const slCosineField&) = delete;

  int LightIndex = -1;
  bool ComputeCellArrays = true;
};

#endif
