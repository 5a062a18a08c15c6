#ifndef slDiffuseColors_h
#define slDiffuseColors_h
/**
 * @file slDiffuseColors.h
 * @brief Internal: per-point k_d from an RGB(A) point array or from a texture
 * looked up at the points' texture coordinates. Not wrapped.
 *
 * slRadianceFilter and slRadianceReference take their base colour through
 * baseColourPerPoint(), so the discrete lighting and the Monte Carlo
 * reference pick the same input, in the same order, with the same errors.
 *
 * Colours are used as given, as VTK and slLightingPass use them: 8-bit
 * values v mean v / 255, float values are taken as they are. No sRGB
 * transfer function is applied on either path, so `shadelab light` and
 * `shadelab render` agree on textured and colour-mapped meshes. Textures are
 * sampled bilinearly with repeat wrapping; texture row 0 is the bottom (as
 * slImageReader gives it). A value that is not finite, or a point whose
 * texture coordinates are not, gives colour 0; other values are clamped to
 * ±kMaxColourValue (SceneLimits.h), so no lighting term can overflow.
 */

#include <glm/glm.hpp>

#include "shadelab/Error.h"

#include <string>
#include <vector>

class vtkImageData;
class vtkPolyData;

namespace shadelab
{

/// Fills @p out with one k_d per point of @p mesh from the point array
/// @p arrayName. Throws shadelab::Error with a one-line reason.
void diffuseFromArray(vtkPolyData* mesh, const std::string& arrayName, std::vector<glm::vec3>& out);

/// Fills @p out from @p texture at the mesh's point texture coordinates.
/// Throws shadelab::Error with a one-line reason.
void diffuseFromTexture(vtkPolyData* mesh, vtkImageData* texture, std::vector<glm::vec3>& out);

/// The base colour (it multiplies k_a and k_d) per point of @p mesh, from
/// the first of these that is given: the point array @p arrayName
/// (diffuseFromArray()), the image file @p textureFileName, read now with
/// slImageReader, or the image @p texture (diffuseFromTexture() for both).
/// A null or empty name and a null image are not given; with none, @p out is
/// left empty. Throws shadelab::Error with a one-line reason (an unreadable
/// file: "FILE: cannot read image: ...").
void baseColourPerPoint(vtkPolyData* mesh, const char* arrayName, const char* textureFileName,
  vtkImageData* texture, std::vector<glm::vec3>& out);

} // namespace shadelab

#endif
