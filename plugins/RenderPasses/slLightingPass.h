#ifndef slLightingPass_h
#define slLightingPass_h
/**
 * @class   slLightingPass
 * @brief   Replaces VTK's lighting with ShadeLab's for every opaque polydata
 *          actor: every lighting model, every light type, true flat, Gouraud
 *          and Phong shading, and component views.
 *
 * slLightingPass is a vtkOpenGLRenderPass that wraps a delegate pass (by
 * default a vtkRenderStepsPass) and rewrites the shaders of every
 * vtkOpenGLPolyDataMapper it draws. The lighting functions come verbatim from
 * the lighting core's slLighting.glsl, the same text the CPU filters compile
 * as C++: there is one copy of every formula.
 *
 * - Models: lambert, phong, blinn-phong and their energy-normalised variants.
 * - Lights: directional, point, spot (cutoff, exponent, smooth edge) and
 *   ambient, up to 16 at once, each with its own ambient, diffuse and
 *   specular colour and min(1, .) attenuation; material emission.
 * - Frequency: Flat lights each face once, at its provoking vertex with the
 *   face normal (cell normals when the mesh has them); Gouraud lights each
 *   vertex in the vertex shader and interpolates the colour (which VTK 9.1's
 *   own "Gouraud" does not: it lights every fragment); Phong lights every
 *   fragment with the interpolated normal.
 * - Lights come from the slScene when one is set (camera lights follow the
 *   camera), otherwise from the renderer's vtkLights. The material comes from
 *   the scene (UseSceneMaterial) or from each actor's vtkProperty. Point or
 *   cell scalar colours and the actor's texture multiply k_a and k_d.
 * - Normal maps (Phong frequency): the property's normal texture
 *   (vtkProperty::SetNormalTexture, tangent space, OpenGL green-up) perturbs
 *   the normal using the mesh's point Tangents. 3-component tangents go
 *   through VTK's own normal mapping; 4-component ones (xyz and handedness
 *   w = +-1, as slPolyDataTangents-style MikkTSpace output) through ShadeLab's,
 *   which honours w.
 * - Component views show only the ambient, diffuse, specular or emission term
 *   (of all lights or of light k), or N.L of light k, in grey or false colour.
 *
 * The frequency, the model, the number and types of the lights and whether a
 * component view is shown are compiled into the shaders (loops unroll, model
 * and type tests fold away, the total carries no component-view code: Mesa's
 * llvmpipe runs both sides of every branch); changing one of them builds a
 * shader variant once, and VTK's shader cache keeps earlier variants, so
 * switching back is cheap. Everything else (light positions, directions,
 * colours, attenuation, spot angles, the material, which component and light
 * a view shows, false colour) is a uniform: changing it costs no shader rebuild.
 *
 * @warning The mapper supplies normals only when the renderer has at least
 * one light switched on; the pass adds a zero-intensity headlight for the
 * frame when there is none. To give the mapper what each frequency needs, the
 * pass sets an actor's interpolation to flat for Flat and away from flat for
 * Gouraud and Phong. Gouraud and Phong need point normals. Only the actor's
 * own texture (vtkActor::SetTexture) is used as base colour. Translucent
 * actors keep VTK's lighting; actors whose property has lighting off are
 * drawn unlit, as VTK draws them.
 *
 * @sa vtkOpenGLRenderPass vtkRenderStepsPass slScene slSceneRenderer
 */

#include "ShadeLabRenderPassesModule.h"

#include <vtkOpenGLRenderPass.h>
#include <vtkSmartPointer.h>

#include <memory>
#include <string>

class slScene;
class vtkRenderer;

class SHADELABRENDERPASSES_EXPORT slLightingPass : public vtkOpenGLRenderPass
{
public:
  static slLightingPass* New();
  vtkTypeMacro(slLightingPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Shading frequencies (values of shadelab::ShadingFrequency).
  enum FrequencyType
  {
    FLAT = 0,
    GOURAUD = 1,
    PHONG = 2
  };

  /// What to show (component views).
  enum ComponentType
  {
    TOTAL = 0,
    AMBIENT = 1,
    DIFFUSE = 2,
    SPECULAR = 3,
    EMISSION = 4,
    COS_THETA = 5
  };

  ///@{
  /// The pass that draws the props (default: a vtkRenderStepsPass).
  void SetDelegatePass(vtkRenderPass* delegate);
  vtkRenderPass* GetDelegatePass();
  ///@}

  ///@{
  /// Lights (and, with UseSceneMaterial, the material) come from this scene.
  /// Setting a scene also copies its model and frequency into the pass.
  /// Without a scene the renderer's vtkLights are used.
  void SetScene(slScene* scene);
  slScene* GetScene();
  ///@}

  ///@{
  /// Lighting model: an SL_MODEL_* value (a row of shadelab/LightingTables.h).
  /// Any other value is an error (vtkErrorMacro) and leaves the model as it was.
  void SetModel(int model);
  vtkGetMacro(Model, int);
  /// By scene-file name; false for an unknown name.
  bool SetModelName(const char* name);
  ///@}

  ///@{
  /// Shading frequency: FLAT, GOURAUD or PHONG.
  void SetFrequency(int frequency);
  vtkGetMacro(Frequency, int);
  bool SetFrequencyName(const char* name);
  ///@}

  ///@{
  /// Take k_a, k_d, k_s, k_e and shininess from the scene (on) or from each
  /// actor's vtkProperty (off). On by default; needs a scene.
  vtkSetMacro(UseSceneMaterial, bool);
  vtkGetMacro(UseSceneMaterial, bool);
  vtkBooleanMacro(UseSceneMaterial, bool);
  ///@}

  ///@{
  /// Component view: TOTAL (default), AMBIENT, DIFFUSE, SPECULAR, EMISSION or
  /// COS_THETA (clamped to that range). Whether a component view is shown at
  /// all is compiled into the shaders (TOTAL carries no code for one): going
  /// from TOTAL to a component or back builds a variant once; switching
  /// between components is a uniform change.
  void SetComponent(int component);
  vtkGetMacro(Component, int);
  ///@}

  ///@{
  /// The light the component view shows: -1 for all lights (N.L shows light 0).
  vtkSetClampMacro(ComponentLight, int, -1, 15);
  vtkGetMacro(ComponentLight, int);
  ///@}

  ///@{
  /// Show components in false colour instead of grey/RGB.
  vtkSetMacro(FalseColor, bool);
  vtkGetMacro(FalseColor, bool);
  vtkBooleanMacro(FalseColor, bool);
  ///@}

  /// The most lights the shaders hold.
  static int GetMaximumNumberOfLights();

  /// Lights used in the last frame (after camera-light transforms).
  int GetNumberOfLightsUsed() const;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* vao = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override;

protected:
  slLightingPass();
  ~slLightingPass() override;

private:
  slLightingPass(const slLightingPass&) = delete;
  void operator=(const slLightingPass&) = delete;

  void PrepareLights(vtkRenderer* renderer);
  void MatchInterpolation(const vtkRenderState* s);
  void MapTangents(const vtkRenderState* s);

  vtkSmartPointer<vtkRenderPass> DelegatePass;
  vtkSmartPointer<slScene> Scene;
  int Model = 2;
  int Frequency = PHONG;
  bool UseSceneMaterial = true;
  int Component = TOTAL;
  int ComponentLight = -1;
  bool FalseColor = false;
  vtkTimeStamp ShaderStageTime;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
