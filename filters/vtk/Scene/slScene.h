#ifndef slScene_h
#define slScene_h
/**
 * @class   slScene
 * @brief   A ShadeLab scene (lights, material, camera, lighting model, shading
 *          frequency) read from JSON and converted to and from VTK objects.
 *
 * slScene reads and writes the JSON scene files described in
 * docs/scene-format.md, with strict validation: every problem is reported as
 * one line naming the file, the key path and the problem, through vtkErrorMacro
 * (slCallOrThrow() gives the line back).
 *
 * It converts both ways between a scene and VTK's own objects, so a VTK
 * user's lights, property and camera can drive ShadeLab and vice versa:
 * ApplyToRenderer() / ApplyToActor() configure VTK's standard pipeline;
 * SetLightsFromVTK(), SetMaterialFromVTK() and SetCameraFromVTK() read VTK
 * objects back.
 *
 * Ambient lights: VTK has none, but it adds every property's ambient colour
 * as if under one white ambient light. ApplyMaterial() therefore sets the
 * property's ambient colour to k_a times the sum of the scene's ambient
 * lights, and SetLightsFromVTK() adds that implicit white ambient light.
 *
 * @warning VTK 9.1's built-in lighting cannot show everything a scene holds.
 * Each conversion lists what it could not carry in GetConversionNotes(): a
 * light's own ambient colour (ignored by VTK's shaders), the min(1, .) clamp of attenuation, a spot's smooth edge, material
 * emission, Blinn-Phong and the normalised models (VTK uses Phong's R.V), and
 * true Gouraud shading (VTK lights every fragment). ShadeLab's render pass
 * carries all of them.
 *
 * @sa vtkLight vtkProperty vtkCamera
 */

#include "ShadeLabSceneModule.h"

#include <vtkObject.h>

#include <memory>
#include <string>

class vtkActor;
class vtkCamera;
class vtkImageData;
class vtkLight;
class vtkLightCollection;
class vtkProperty;
class vtkRenderer;

#ifndef __VTK_WRAP__
namespace shadelab
{
struct Scene;
}
#endif

class SHADELABSCENE_EXPORT slScene : public vtkObject
{
public:
  static slScene* New();
  vtkTypeMacro(slScene, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Read / write a JSON scene file. False on failure, after
  /// vtkErrorMacro with the one-line reason; the scene is then unchanged.
  /// Writing is all or nothing.
  bool ReadFile(const char* path);
  bool WriteFile(const char* path);
  ///@}

  /// Parse JSON text; @p nameForMessages stands for the file in messages.
  bool ReadString(const char* jsonText, const char* nameForMessages = "(string)");

  /// The scene as JSON text.
  std::string ToJSON() const;

  /// What the last conversion of the lights and the last of the material,
  /// to or from VTK, could not carry, one item per line ("" when nothing was
  /// lost). A scene applied to a renderer and an actor (in either order)
  /// lists what both lose.
  const char* GetConversionNotes();

  ///@{
  /// Lighting model by its scene-file name: one of the models of the
  /// lighting table (shadelab/LightingTables.h), "lambert", "phong",
  /// "blinn-phong", their "-normalized" variants, "cook-torrance-ggx" and the
  /// others `shadelab render --help` lists. SetModelName() returns false for
  /// an unknown name, which is an error (vtkErrorMacro) naming the models.
  std::string GetModelName() const;
  bool SetModelName(const char* name);
  ///@}

  ///@{
  /// Shading frequency by name ("flat", "gouraud", "phong"); another name
  /// is an error (vtkErrorMacro): false, and the frequency as it was.
  std::string GetFrequencyName() const;
  bool SetFrequencyName(const char* name);
  ///@}

  int GetNumberOfLights() const;
  int GetImageWidth() const;
  int GetImageHeight() const;

  /// The diffuse texture resolved against the scene file's folder, or "".
  std::string GetDiffuseTexturePath() const;
  /// Reads the material's diffuse texture (GetDiffuseTexturePath()) into
  /// @p image, as it is stored (ApplyToActor() and slRadianceFilter each
  /// make their own use of its values); @p image is left empty, and true
  /// returned, when the scene has none. False, after vtkErrorMacro naming
  /// the image, the reason and "material.diffuseTexture of FILE", if it
  /// cannot be read.
  bool ReadDiffuseTexture(vtkImageData* image);
  /// The .brdf file (brdf.file) resolved against the scene file's folder, or "".
  std::string GetBrdfFilePath() const;

  ///@{
  /// Scene to VTK. ApplyToRenderer() sets the background, replaces the lights
  /// and places the camera (fitting the visible props if the scene gives no
  /// camera position, so call it after adding the actors). ApplyToActor() sets
  /// the property, interpolation and diffuse texture; false, after
  /// vtkErrorMacro naming the texture file, if that cannot be read. The
  /// texture shows 8-bit images as v / 255 and deeper ones (16-bit, EXR,
  /// HDR) as their float values, as stored, like slRadianceFilter's lookup
  /// (docs/scene-format.md, "Diffuse textures").
  void ApplyToRenderer(vtkRenderer* renderer);
  /// ApplyToRenderer() with the camera fitted to @p bounds for an image of
  /// @p width x @p height (see ApplyCamera()) instead of the visible props.
  void ApplyToRenderer(vtkRenderer* renderer, const double bounds[6], int width, int height);
  bool ApplyToActor(vtkActor* actor);
  void ApplyLights(vtkRenderer* renderer);
  void ApplyMaterial(vtkProperty* property);
  ///@}

  ///@{
  /// Places @p camera as the scene says for an image of @p width x @p height
  /// pixels showing @p bounds (xmin, xmax, ymin, ymax, zmin, zmax): the one
  /// camera rule (shadelab/CameraPlacement.h) that every renderer and CPU
  /// lighting filter uses. The bounds are an input so that a caller can pass
  /// those of the whole mesh when it holds only a piece. Sizes below 1 mean
  /// the scene's imageSize.
  void ApplyCamera(vtkCamera* camera, const double bounds[6], int width, int height);
  /// ApplyCamera() on the renderer's active camera with the bounds of its
  /// visible props and its size (the scene's imageSize while it has no window),
  /// then resets its clipping range.
  void ApplyCamera(vtkRenderer* renderer);
  ///@}

  ///@{
  /// VTK to scene: replace the scene's lights, material or camera.
  void SetLightsFromVTK(vtkLightCollection* lights);
  void SetMaterialFromVTK(vtkProperty* property);
  void SetCameraFromVTK(vtkCamera* camera);
  ///@}

#ifndef __VTK_WRAP__
  /// The scene itself, for C++ users of the lighting core.
  const shadelab::Scene& GetScene() const;
  void SetScene(const shadelab::Scene& scene);
#endif

protected:
  slScene();
  ~slScene() override;

private:
  slScene(const slScene&) = delete;
  void operator=(const slScene&) = delete;

  std::unique_ptr<shadelab::Scene> Data;
  // Notes of the last conversion of each part: ApplyLights() and
  // SetLightsFromVTK() replace LightNotes, ApplyMaterial() and
  // SetMaterialFromVTK() MaterialNotes, so that one part's conversion does
  // not drop what the other's found.
  std::string LightNotes;
  std::string MaterialNotes;
  std::string ConversionNotes; ///< both, as GetConversionNotes() returns them
};

#endif
