#ifndef slPolyDataTangents_h
#define slPolyDataTangents_h
/**
 * @class   slPolyDataTangents
 * @brief   MikkTSpace-style tangent frames from texture coordinates: a
 *          4-component point array "Tangents" (xyz, handedness w = ±1).
 *
 * For every polygon the tangent is the surface direction of increasing u;
 * at each vertex the polygons' tangents are projected onto the plane of the
 * vertex normal, normalised, weighted by the corner angle and summed, then
 * orthogonalised to the normal and normalised (as MikkTSpace). The
 * bitangent a shader should use is B = w · (N × T); w is −1 where the UV map
 * is mirrored.
 *
 * Seams: points at UV seams are already separate points (they differ in
 * texture coordinates, see slMeshReader), so their frames are computed
 * apart. A point where mirrored and unmirrored polygons meet (a mirror seam)
 * is duplicated: the copy, with all its point data, takes the mirrored
 * polygons and w = −1.
 *
 * The input needs point texture coordinates (the active TCoords): without
 * them the filter reports an error and gives an empty output. Point normals
 * are the active point normals; when there are none they are computed with
 * slPolyDataNormals (angle weighting, no splitting). Strips are turned into
 * triangles; vertex and line cells are passed through with a warning.
 * Polygons with zero UV area contribute nothing; a point without any
 * contribution gets a unit tangent orthogonal to its normal and w = +1.
 *
 * @warning The result matches MikkTSpace where its assumptions hold (one
 * normal per point, triangles); MikkTSpace's own splitting of points whose
 * corners' tangents differ by more than a threshold is not done.
 *
 * @sa slPolyDataNormals vtkPolyDataTangents slNormalMapFilter
 */

#include "ShadeLabNormalsModule.h"

#include "slPolyDataFilter.h"

class SHADELABNORMALS_EXPORT slPolyDataTangents : public slPolyDataFilter
{
public:
  static slPolyDataTangents* New();
  vtkTypeMacro(slPolyDataTangents, slPolyDataFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Points duplicated along mirror seams by the last update.
  vtkGetMacro(NumberOfSplitPoints, vtkIdType);

protected:
  slPolyDataTangents();
  ~slPolyDataTangents() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slPolyDataTangents(const slPolyDataTangents&) = delete;
  void operator=(const slPolyDataTangents&) = delete;

  vtkIdType NumberOfSplitPoints = 0;
};

#endif
