#ifndef slBumpMapFilter_h
#define slBumpMapFilter_h
/**
 * @class   slBumpMapFilter
 * @brief   Perturbs point normals with the gradient of a height image.
 *
 * The height h(u, v) is channel 0 of the image (0..1 for 8-bit files; with
 * InvertHeight, 1 − value, for depth maps such as Bevy's), sampled
 * bilinearly and repeating. Its gradient, by central differences one texel
 * apart, gives the tangent-space normal normalise(−Scale ∂h/∂u,
 * −Scale ∂h/∂v, 1) of the surface displaced by Scale · h along its normal
 * when u and v are arc length (a plane with UVs equal to its coordinates);
 * it is taken to object space with the point's frame (T, B = w·N×T, N) and
 * replaces the point array "Normals".
 *
 * Normals and "Tangents" are used when present, otherwise computed. No
 * texture coordinates, NaN coordinates, or an unreadable image give an
 * error naming the problem (and the file) and an empty output.
 *
 * @warning The slope is exact only where u and v are arc length: on a mesh
 * whose texture coordinates are stretched, the bumps steepen or flatten
 * with the stretch (Scale is in texture units). Only the normals change;
 * the points stay where they are (slDisplacementFilter moves them).
 *
 * @sa slNormalMapFilter slDisplacementFilter
 */

#include "ShadeLabNormalsModule.h"

#include "slSurfaceDetailFilter.h"

class SHADELABNORMALS_EXPORT slBumpMapFilter : public slSurfaceDetailFilter
{
public:
  static slBumpMapFilter* New();
  vtkTypeMacro(slBumpMapFilter, slSurfaceDetailFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Height scale in UV units, −100..100. 0.05 by default.
  vtkSetClampMacro(Scale, double, -100.0, 100.0);
  vtkGetMacro(Scale, double);
  ///@}

  ///@{
  /// Use 1 − value as the height (depth maps). Off by default.
  vtkSetMacro(InvertHeight, bool);
  vtkGetMacro(InvertHeight, bool);
  vtkBooleanMacro(InvertHeight, bool);
  ///@}

protected:
  slBumpMapFilter();
  ~slBumpMapFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slBumpMapFilter(const slBumpMapFilter&) = delete;
  void operator=(const slBumpMapFilter&) = delete;

  double Scale = 0.05;
  bool InvertHeight = false;
};

#endif
