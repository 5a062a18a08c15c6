#ifndef slLobesOnMesh_h
#define slLobesOnMesh_h
/**
 * @class   slLobesOnMesh
 * @brief   BRDF lobe glyphs on a mesh: at chosen or sampled points, each lobe
 *          in that point's normal frame for the incident direction of the
 *          scene's light there.
 *
 * For every selected point P with normal N, the lobe r(w_o) = f_r(L, w_o)
 * (optionally x cos theta_o) is drawn around P over the hemisphere of N,
 * with L = the direction from P toward the chosen light (for point and spot
 * lights it differs from point to point). f_r is slBRDF() of
 * slLighting.glsl with the scene's material (mean of R, G, B) and model.
 *
 * Points: SetPointIds() chooses them; otherwise NumberOfLobes points are
 * taken at an even stride through the lit points (N.L above slBRDF's grazing
 * limit, so each shows a lobe), or all of them if fewer are lit.
 * GetNumberOfLobesDrawn() tells how many lobes the output holds. All lobes share one scale:
 * the largest r over all lobes becomes Scale x the input's bounding-box
 * diagonal. The output holds only the lobes: point arrays "BRDF" (r) and
 * "PointId" (the input point each lobe belongs to).
 *
 * @warning Chosen points (SetPointIds) whose normal is zero, or that face
 * away from the light (N.L <= 0), get no lobe: f_r is zero there.
 *
 * @sa slBRDFLobeSource slLitFilter
 */

#include "ShadeLabLightingModule.h"
#include "slLitFilter.h"

class vtkIdList;

class SHADELABLIGHTING_EXPORT slLobesOnMesh : public slLitFilter
{
public:
  static slLobesOnMesh* New();
  vtkTypeMacro(slLobesOnMesh, slLitFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The light whose direction is used; -1 (default): the first light that has one.
  /// An index out of range or of an ambient light is an error at the update.
  vtkSetClampMacro(LightIndex, int, -1, VTK_INT_MAX);
  vtkGetMacro(LightIndex, int);
  ///@}

  ///@{
  /// The points to put lobes on; null (default): NumberOfLobes sampled points.
  virtual void SetPointIds(vtkIdList* ids);
  vtkGetObjectMacro(PointIds, vtkIdList);
  ///@}

  ///@{
  /// How many points to sample when no PointIds are given (default 16).
  vtkSetClampMacro(NumberOfLobes, int, 1, 100000);
  vtkGetMacro(NumberOfLobes, int);
  ///@}

  /// Lobes in the last output: the chosen or sampled points that are lit.
  vtkGetMacro(NumberOfLobesDrawn, int);

  ///@{
  /// Size of the largest lobe as a fraction of the bounding-box diagonal (default 0.1).
  vtkSetClampMacro(Scale, double, 0.0, 100.0);
  vtkGetMacro(Scale, double);
  ///@}

  ///@{
  /// Multiply r by cos theta_o. Off by default.
  vtkSetMacro(MultiplyByCosine, bool);
  vtkGetMacro(MultiplyByCosine, bool);
  vtkBooleanMacro(MultiplyByCosine, bool);
  ///@}

  ///@{
  /// Lobe tessellation: rings and segments (defaults 12, 24).
  vtkSetClampMacro(ThetaResolution, int, 1, 256);
  vtkGetMacro(ThetaResolution, int);
  vtkSetClampMacro(PhiResolution, int, 3, 512);
  vtkGetMacro(PhiResolution, int);
  ///@}

protected:
  slLobesOnMesh();
  ~slLobesOnMesh() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slLobesOnMesh(const slLobesOnMesh&) = delete;
  void operator=(const slLobesOnMesh&) = delete;

  int LightIndex = -1;
  vtkIdList* PointIds = nullptr;
  int NumberOfLobes = 16;
  int NumberOfLobesDrawn = 0;
  double Scale = 0.1;
  bool MultiplyByCosine = false;
  int ThetaResolution = 12;
  int PhiResolution = 24;
};

#endif
