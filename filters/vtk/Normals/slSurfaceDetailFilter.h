#ifndef slSurfaceDetailFilter_h
#define slSurfaceDetailFilter_h
/**
 * @class   slSurfaceDetailFilter
 * @brief   Base of the filters that add surface detail from an image
 *          sampled at each point's texture coordinates.
 *
 * slNormalMapFilter, slBumpMapFilter and slDisplacementFilter read an image
 * (FileName) and sample it at each point's texture coordinates, in the
 * point's surface frame (normal, tangent, handedness). This class holds the
 * file name and the first step they share (PrepareDetail): check the
 * filter's own parameter, find the frames, read the image and check the
 * channels the filter samples; any problem is reported on one line naming
 * it (and the file) and leaves an empty output.
 *
 * @sa slNormalMapFilter slBumpMapFilter slDisplacementFilter slPolyDataFilter
 */

#include "ShadeLabNormalsModule.h"

#include "slPolyDataFilter.h"

struct slSurfaceFrames;
namespace slnormals
{
struct Texture;
}

class SHADELABNORMALS_EXPORT slSurfaceDetailFilter : public slPolyDataFilter
{
public:
  vtkTypeMacro(slSurfaceDetailFilter, slPolyDataFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The image: a normal map or a height map, as the filter says. Any
  /// format slImageReader reads.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

protected:
  slSurfaceDetailFilter();
  ~slSurfaceDetailFilter() override;

  /// Checks that the filter's parameter @p parameterName (value
  /// @p parameter) is finite, then fills @p frames from @p input (normals,
  /// and with @p needTangents tangents, computed where absent) and
  /// @p texture from FileName, whose first @p channelsRead channels must be
  /// finite. False after reporting the first problem (Fail(): one line,
  /// an empty @p output); the caller's RequestData then returns 0.
  bool PrepareDetail(vtkPolyData* input, vtkPolyData* output, const char* parameterName, double parameter,
    bool needTangents, int channelsRead, slSurfaceFrames& frames, slnormals::Texture& texture);

  char* FileName = nullptr;

private:
  slSurfaceDetailFilter(const slSurfaceDetailFilter&) = delete;
  void operator=(const slSurfaceDetailFilter&) = delete;
};

#endif
