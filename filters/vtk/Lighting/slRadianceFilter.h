#ifndef slRadianceFilter_h
#define slRadianceFilter_h
/**
 * @class   slRadianceFilter
 * @brief   The whole lighting equation evaluated per point: point arrays
 *          Ambient, Diffuse, Specular, Emission and Radiance (RGB float,
 *          linear), optionally one array per light (Radiance_0, Radiance_1, ...).
 *
 * Each point is shaded with its point normal, seen from the eye, under every
 * light of the scene (or of VTK's own lights, see slLitFilter), by
 * slShadeLight() from slLighting.glsl, the same code the GPU render pass
 * runs. Radiance = Ambient + Diffuse + Specular + Emission; emission is the
 * material's k_e, added once.
 *
 * The mesh can colour the material: an RGB(A) point array
 * (SetDiffuseColorArrayName()) or a texture sampled at the point texture
 * coordinates (SetDiffuseTexture()) is a base colour that multiplies k_a and
 * k_d at each point, exactly as scalar colours and the actor's texture do in
 * slLightingPass (with k_a = k_d = 1 it stands in for k_d). Colours are used
 * as VTK and the pass use them: 8-bit values v mean v / 255 (no sRGB
 * decoding), float values as they are. The array wins over the texture
 * file (SetDiffuseTextureFileName()), which wins over the texture;
 * slRadianceReference takes the same three the same way (one shared
 * function, so the two filters cannot disagree on which colour applies).
 *
 * Input arrays are passed through. The loop over points runs in parallel with
 * vtkSMPTools.
 *
 * @warning This is per-vertex (Gouraud-style) lighting; no shadows and no
 * interreflection: it is the local lighting equation, light by light.
 * Per-light arrays hold ambient + diffuse + specular of that light.
 *
 * @sa slLitFilter slCosineField slRadianceReference slScene
 */

#include "ShadeLabLightingModule.h"
#include "slLitFilter.h"

#include <string>

class vtkImageData;

class SHADELABLIGHTING_EXPORT slRadianceFilter : public slLitFilter
{
public:
  static slRadianceFilter* New();
  vtkTypeMacro(slRadianceFilter, slLitFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Also write Radiance_0, Radiance_1, ...: light i's ambient + diffuse + specular. Off by default.
  vtkSetMacro(PerLightArrays, bool);
  vtkGetMacro(PerLightArrays, bool);
  vtkBooleanMacro(PerLightArrays, bool);
  ///@}

  ///@{
  /// Name of an RGB(A) point array that stands in for k_d; "" (default): none.
  vtkSetStringMacro(DiffuseColorArrayName);
  vtkGetStringMacro(DiffuseColorArrayName);
  ///@}

  ///@{
  /// A texture (e.g. from slImageReader) that stands in for k_d, looked up at
  /// the point texture coordinates. Null (default): none.
  virtual void SetDiffuseTexture(vtkImageData* image);
  vtkGetObjectMacro(DiffuseTexture, vtkImageData);
  ///@}

  ///@{
  /// An image file (any format slImageReader reads) that stands in for k_d
  /// like SetDiffuseTexture(), read at each update; it takes precedence over
  /// SetDiffuseTexture(). "" or null (default): none. For ParaView, whose
  /// properties are plain values.
  vtkSetStringMacro(DiffuseTextureFileName);
  vtkGetStringMacro(DiffuseTextureFileName);
  ///@}

  vtkMTimeType GetMTime() override;

protected:
  slRadianceFilter();
  ~slRadianceFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slRadianceFilter(const slRadianceFilter&) = delete;
  void operator=(const slRadianceFilter&) = delete;

  bool PerLightArrays = false;
  char* DiffuseColorArrayName = nullptr;
  vtkImageData* DiffuseTexture = nullptr;
  char* DiffuseTextureFileName = nullptr;
};

#endif
