#ifndef slDisplacementFilter_h
#define slDisplacementFilter_h
/**
 * @class   slDisplacementFilter
 * @brief   Moves points along their normals by height × scale, then
 *          recomputes the normals.
 *
 * The height h(u, v) is channel 0 of the image (0..1 for 8-bit files; with
 * InvertHeight, 1 − value), sampled bilinearly at each point's texture
 * coordinates, repeating. Each point moves to P + Scale · h · N; the point
 * array "Normals" is then recomputed with slPolyDataNormals (angle
 * weighting, no splitting, so points and their data stay as they are).
 *
 * Points at UV seams are separate points with different texture
 * coordinates: where the two sides' heights differ the surface tears. Use
 * heights that match along seams. No texture coordinates, NaN coordinates,
 * an unreadable image, or a NaN or infinite height in it (channel 0) give an
 * error and an empty output.
 *
 * @sa slBumpMapFilter slNormalMapFilter vtkWarpVector
 */

#include "ShadeLabNormalsModule.h"

#include "slSurfaceDetailFilter.h"

class SHADELABNORMALS_EXPORT slDisplacementFilter : public slSurfaceDetailFilter
{
public:
  static slDisplacementFilter* New();
  vtkTypeMacro(slDisplacementFilter, slSurfaceDetailFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Displacement of height 1, in mesh units, −1e6..1e6. 0.05 by default.
  vtkSetClampMacro(Scale, double, -1e6, 1e6);
  vtkGetMacro(Scale, double);
  ///@}

  ///@{
  /// Use 1 − value as the height (depth maps). Off by default.
  vtkSetMacro(InvertHeight, bool);
  vtkGetMacro(InvertHeight, bool);
  vtkBooleanMacro(InvertHeight, bool);
  ///@}

protected:
  slDisplacementFilter();
  ~slDisplacementFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slDisplacementFilter(const slDisplacementFilter&) = delete;
  void operator=(const slDisplacementFilter&) = delete;

  double Scale = 0.05;
  bool InvertHeight = false;
};

#endif
