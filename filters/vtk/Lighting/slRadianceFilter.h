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
 * The mesh can colour the material (slBaseColouredFilter): a point array
 * or a texture gives a base colour that multiplies k_a and k_d at each point,
 * exactly as scalar colours and the actor's texture do in slLightingPass.
 * slRadianceReference takes it through the same base class, so the two
 * filters cannot disagree on which colour applies.
 *
 * Input arrays are passed through. The loop over points runs in parallel with
 * vtkSMPTools.
 *
 * @warning This is per-vertex (Gouraud-style) lighting; no shadows and no
 * interreflection: it is the local lighting equation, light by light.
 * Per-light arrays hold ambient + diffuse + specular of that light.
 *
 * @sa slBaseColouredFilter slLitFilter slCosineField slRadianceReference slScene
 */

#include "ShadeLabLightingModule.h"
#include "slBaseColouredFilter.h"

class SHADELABLIGHTING_EXPORT slRadianceFilter : public slBaseColouredFilter
{
public:
  static slRadianceFilter* New();
  vtkTypeMacro(slRadianceFilter, slBaseColouredFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Also write Radiance_0, Radiance_1, ...: light i's ambient + diffuse + specular. Off by default.
  vtkSetMacro(PerLightArrays, bool);
  vtkGetMacro(PerLightArrays, bool);
  vtkBooleanMacro(PerLightArrays, bool);
  ///@}

protected:
  slRadianceFilter();
  ~slRadianceFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slRadianceFilter(const slRadianceFilter&) = delete;
  void operator=(const slRadianceFilter&) = delete;

  bool PerLightArrays = false;
};

#endif
