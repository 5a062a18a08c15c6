#ifndef slBaseColouredFilter_h
#define slBaseColouredFilter_h
/**
 * @class   slBaseColouredFilter
 * @brief   Base of the lit filters whose material the mesh can colour: a
 *          base colour per point, from a point array or a texture, that
 *          multiplies k_a and k_d.
 *
 * Three inputs, in this order of precedence: an RGB(A) point array
 * (SetDiffuseColorArrayName()), else an image file read at each update
 * (SetDiffuseTextureFileName(), for ParaView), else an image
 * (SetDiffuseTexture(), e.g. from slImageReader or a scene's
 * material.diffuseTexture through slReadSceneTexture()). A texture is
 * sampled at the point texture coordinates. The colour multiplies k_a and
 * k_d at each point, exactly as scalar colours and the actor's texture do in
 * slLightingPass (with k_a = k_d = 1 it stands in for k_d). Colours are used
 * as VTK and the pass use them: 8-bit values v mean v / 255 (no sRGB
 * decoding), float values as they are.
 *
 * Subclasses take the colours through GetBaseColours(), one function
 * (baseColourPerPoint(), slDiffuseColors.h) for all of them, so they cannot
 * disagree on which input applies, how it is sampled or how it fails: a
 * missing or wrongly sized array, an unreadable file or a texture on a mesh
 * without texture coordinates is vtkErrorMacro of one line, an empty output
 * and a failed request. The filters read only the array or texture they are
 * given, never the scene's. PrepareShading() gives the colours together
 * with the rest of the radiance kernel's input (points, normals, tangents,
 * lighting), so that slRadianceFilter and the discrete radiance of
 * slRadianceReference read the same input.
 *
 * The texture's modification time counts as the filter's (GetMTime()).
 *
 * @sa slLitFilter slRadianceFilter slRadianceReference slImageReader
 */

#include "ShadeLabLightingModule.h"
#include "slLitFilter.h"

#ifndef __VTK_WRAP__
#include <glm/fwd.hpp> // glm::vec3, the colours' type

#include <memory>
#include <vector>

namespace shadelab
{
struct ShadingInputs; // slShadingInputs.h, private to the module
}
#endif

class vtkImageData;

class SHADELABLIGHTING_EXPORT slBaseColouredFilter : public slLitFilter
{
public:
  vtkAbstractTypeMacro(slBaseColouredFilter, slLitFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Name of an RGB(A) point array that multiplies k_a and k_d per point;
  /// it takes precedence over both textures. "" or null (default): none.
  vtkSetStringMacro(DiffuseColorArrayName);
  vtkGetStringMacro(DiffuseColorArrayName);
  ///@}

  ///@{
  /// A texture (e.g. from slImageReader or slReadSceneTexture()) that
  /// multiplies k_a and k_d, looked up at the point texture coordinates; the
  /// input must have them. Null (default): none.
  virtual void SetDiffuseTexture(vtkImageData* image);
  vtkGetObjectMacro(DiffuseTexture, vtkImageData);
  ///@}

  ///@{
  /// An image file (any format slImageReader reads) used like
  /// SetDiffuseTexture(), read at each update; it takes precedence over
  /// SetDiffuseTexture(). "" or null (default): none. For ParaView, whose
  /// properties are plain values.
  vtkSetStringMacro(DiffuseTextureFileName);
  vtkGetStringMacro(DiffuseTextureFileName);
  ///@}

  /// The filter's time and the texture's, whichever is later.
  vtkMTimeType GetMTime() override;

protected:
  slBaseColouredFilter();
  ~slBaseColouredFilter() override;

#ifndef __VTK_WRAP__
  /// Sets @p base to the base colour of every point of @p input from the
  /// first input given (left empty when none is) and returns true; or
  /// reports the one-line reason with vtkErrorMacro, empties @p output and
  /// returns false.
  bool GetBaseColours(vtkPolyData* input, vtkPolyData* output, std::vector<glm::vec3>& base);

  /// What the radiance kernel reads for @p input under @p setup (after
  /// PrepareLighting()): GetBaseColours(), then GetTangents(), then @p output
  /// made a shallow copy of @p input, then the kernel's input over the
  /// points, normals, tangents and base colours. Null once a step has
  /// failed (it has reported and emptied @p output).
  std::unique_ptr<const shadelab::ShadingInputs> PrepareShading(
    vtkPolyData* input, vtkPolyData* output, const shadelab::LightingSetup& setup);
#endif

private:
  slBaseColouredFilter(const slBaseColouredFilter&) = delete;
  void operator=(const slBaseColouredFilter&) = delete;

  char* DiffuseColorArrayName = nullptr;
  vtkImageData* DiffuseTexture = nullptr;
  char* DiffuseTextureFileName = nullptr;
};

#endif
