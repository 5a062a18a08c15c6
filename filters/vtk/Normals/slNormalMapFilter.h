#ifndef slNormalMapFilter_h
#define slNormalMapFilter_h
/**
 * @class   slNormalMapFilter
 * @brief   Perturbs point normals with a tangent-space normal map.
 *
 * The image (any format OpenImageIO reads, through slImageReader) is sampled
 * bilinearly at each point's texture coordinates, repeating outside [0, 1].
 * RGB in 0..1 decodes to the tangent-space normal 2·RGB − 1; OpenGL maps
 * (green up, the default) are read as they are, DirectX maps (green down)
 * with green flipped. Strength scales the x and y of the decoded normal
 * (0: unchanged normals, 1: the map as authored). The result, in the frame
 * (T, B = w·N×T, N) of the point, replaces the point array "Normals".
 *
 * Normals and "Tangents" are used when present, otherwise computed with
 * slPolyDataNormals and slPolyDataTangents. No texture coordinates, NaN
 * coordinates, or an unreadable image give an error naming the problem (and
 * the file) and an empty output.
 *
 * @warning Normals are perturbed at the points only: detail finer than the
 * mesh is lost (a per-pixel normal map is a shader's job); this filter is for
 * baking, previews and tests.
 *
 * @sa slBumpMapFilter slDisplacementFilter slPolyDataTangents
 */

#include "ShadeLabNormalsModule.h"

#include "slSurfaceDetailFilter.h"

class SHADELABNORMALS_EXPORT slNormalMapFilter : public slSurfaceDetailFilter
{
public:
  static slNormalMapFilter* New();
  vtkTypeMacro(slNormalMapFilter, slSurfaceDetailFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Scale of the map's x and y, 0..10. 1 by default.
  vtkSetClampMacro(Strength, double, 0.0, 10.0);
  vtkGetMacro(Strength, double);
  ///@}

  ///@{
  /// Green points down (DirectX maps). Off by default (OpenGL, green up).
  vtkSetMacro(GreenDown, bool);
  vtkGetMacro(GreenDown, bool);
  vtkBooleanMacro(GreenDown, bool);
  ///@}

protected:
  slNormalMapFilter();
  ~slNormalMapFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slNormalMapFilter(const slNormalMapFilter&) = delete;
  void operator=(const slNormalMapFilter&) = delete;

  double Strength = 1.0;
  bool GreenDown = false;
};

#endif
