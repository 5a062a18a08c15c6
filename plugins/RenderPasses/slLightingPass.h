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
 * - Models: every row of shadelab/LightingTables.h (Lambert, Phong and
 *   Blinn-Phong, their energy-normalised variants, the microfacet and the
 *   anisotropic models); SetModel() takes an SL_MODEL_* value.
 * - Lights: directional, point, spot (cutoff, exponent, smooth edge) and
 *   ambient, up to GetMaximumNumberOfLights() at once, each with its own ambient, diffuse and
 *   specular colour and min(1, .) attenuation; material emission.
 * - Frequency: Flat lights each face once, at its provoking vertex with the
 *   face normal (cell normals when the mesh has them); Gouraud lights each
 *   vertex in the vertex shader and interpolates the colour (which VTK 9.1's
 *   own "Gouraud" does not: it lights every fragment); Phong lights every
 *   fragment with the interpolated normal.
 * - Lights come from the slScene when one is set (camera lights follow the
 *   camera), otherwise from the renderer's vtkLights, as VTK reads them:
 *   switched-off lights are left out, and with none switched on VTK's
 *   automatic headlight is created (AutomaticLightCreation) or, without it,
 *   the actors are drawn unlit in their ambient + diffuse colour. The
 *   material comes from the scene (UseSceneMaterial) or from each actor's
 *   vtkProperty. Point or cell scalar colours take the place of the
 *   property's ambient and diffuse colours, as in VTK (its intensities
 *   stay), and multiply the scene's k_a and k_d; the actor's texture
 *   multiplies k_a and k_d.
 * - Backface property (vtkActor::SetBackfaceProperty), as in VTK: with the
 *   actors' vtkProperty material, faces seen from behind take its ambient,
 *   diffuse and specular colours and coefficients, its specular power and
 *   its opacity, lit with the flipped normal (as faces seen from behind
 *   always are); under shown scalars VTK leaves it unused, and so does the
 *   pass. The scene's material is both sides'. Only actors with one get shaders
 *   with a second material (lights uploaded without k_a, k_d, k_s, which
 *   the shader multiplies in per side); other actors' shaders and uniforms
 *   carry none of it. As in VTK, a backface property given or taken away
 *   after the actor was drawn shows once the actor's shaders are rebuilt
 *   (after a change to its vtkProperty, for instance).
 * - Normal maps (Phong frequency): the property's normal texture
 *   (vtkProperty::SetNormalTexture, tangent space, OpenGL green-up) perturbs
 *   the normal using the mesh's point Tangents. 3-component tangents go
 *   through VTK's own normal mapping; 4-component ones (xyz and handedness
 *   w = +-1, as slPolyDataTangents-style MikkTSpace output) through ShadeLab's,
 *   which honours w.
 * - Component views show only the ambient, diffuse, specular or emission term
 *   (of all lights or of light k), or N.L of light k, in grey or false colour.
 * - BRDF Explorer .brdf files (LoadBrdfFile, SetBrdfText): the file's GLSL
 *   function BRDF(L, V, N, X, Y) shades in place of the model's diffuse and
 *   specular factors, at every frequency. Each light gives BRDF times its
 *   diffuse colour (times intensity) times its reach (attenuation, spot
 *   factor) times max(N.L, 0), computed by the same slLighting.glsl
 *   functions; ambient and emission are the model's. The reflection is the
 *   diffuse term: the diffuse component view shows it, the specular view is
 *   black, and scalar colours and the texture multiply it as they multiply
 *   k_d. X, Y are the mesh's 4-component Tangents made orthogonal to N with
 *   Y = w (N x X) (slTangentX, slBitangentY of slLighting.glsl); without
 *   them, the frame slTangentX builds from N alone, in view coordinates.
 *   The file's parameters are uniforms.
 *
 * The frequency, the model, the number and types of the lights and whether a
 * component view is shown are compiled into the shaders (loops unroll, model
 * and type tests fold away, the total carries no component-view code: Mesa's
 * llvmpipe runs both sides of every branch); changing one of them builds a
 * shader variant once, and VTK's shader cache keeps earlier variants, so
 * switching back is cheap. A .brdf file's shader text is compiled in the same
 * way (one variant per text); its parameter values, like everything else
 * (light positions, ...), are uniforms. Everything else (light positions, directions,
 * colours, attenuation, spot angles, the material, which component and light
 * a view shows, false colour) is a uniform: changing it costs no shader rebuild.
 *
 * @warning The mapper supplies normals only when the renderer has at least
 * one light switched on; with a scene and no such vtkLight the pass adds a
 * zero-intensity headlight for the frame. To give the mapper what each
 * frequency needs, the pass sets the interpolation of each actor it lights
 * to flat for Flat and, for Gouraud and Phong, to the one it found or Phong
 * where that is flat, before each frame and only where it differs (a
 * change rebuilds the actor's shaders). It gives the value it found back
 * to each property still alive that still has the value the pass set (a
 * value the user gave since stays): when the pass of a renderer it drew
 * changes (vtkRenderer::SetPass, seen through the renderer's
 * ModifiedEvent), in ReleaseGraphicsResources() (VTK calls that when the
 * renderer leaves its window and when the window is finalised) and when
 * the pass is freed (VTK's mappers hold it until they draw again: if that
 * is in a frame, once the frame is drawn). A renderer whose pass changes
 * between passes around this one, the pass drawn again under another,
 * has it given back on the first change only. Gouraud and Phong need point
 * normals (a mesh without is shaded flat, with a warning). Only the actor's
 * own texture (vtkActor::SetTexture) is used as base colour; as in VTK, it
 * colours faces seen from behind only while the property's
 * ShowTexturesOnBackface is on (the default; off gets a shader variant with
 * the side test, only for such actors). Not lit by the pass, and drawn as
 * VTK draws them: translucent actors (VTK's lighting), actors whose property has lighting
 * off, lines and points that VTK leaves unlit (without point normals, or
 * with flat interpolation: ambient + diffuse colour), volumes and other
 * non-polydata props. Not supported: shadows (vtkShadowMapPass as the
 * delegate: the picture has none, and the pass warns once) and other passes that rewrite VTK's
 * lighting code, and VTK's PBR interpolation (lit with the pass's model and
 * the property's ambient, diffuse and specular). A .brdf file's GLSL is compiled once on
 * its own (with ShadeLab's declarations) before it goes into VTK's shaders:
 * a compile error is one line, GetBrdfError(), and the meshes are drawn
 * with the built-in model instead; a clash with a name of VTK's own shader
 * code (a parameter called "opacity", say) is reported by VTK.
 *
 * @warning More lights than GetMaximumNumberOfLights() do not fit the
 * shaders: the pass draws the first ones and reports the others as dropped
 * with vtkErrorMacro (an ErrorEvent observers see; the picture then differs
 * from the CPU filters, which use every light), once per pass until the
 * lights fit again. `shadelab render` and `compare` refuse such a scene
 * before drawing (GetLightCountProblem()).
 *
 * @sa vtkOpenGLRenderPass vtkRenderStepsPass slScene slSceneRenderer
 */

#include "ShadeLabRenderPassesModule.h"

#include <vtkOpenGLRenderPass.h>
#include <vtkSmartPointer.h>

#include <memory>
#include <string>
#include <vector>

#ifndef __VTK_WRAP__
#include <glm/vec3.hpp>
#endif

namespace shadelab
{
struct BrdfFile;
}
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
  /// Setting a scene also copies its model, its frequency and its .brdf file
  /// (brdf.file and brdf.parameters, or none) into the pass; a .brdf file
  /// that cannot be read or a bad parameter value is an error
  /// (vtkErrorMacro, GetBrdfError()) and leaves the pass with the model.
  /// Without a scene the renderer's vtkLights are used.
  void SetScene(slScene* scene);
  slScene* GetScene();
  ///@}

  ///@{
  /// Lighting model: an SL_MODEL_* value (a row of shadelab/LightingTables.h).
  /// Any other value is an error (vtkErrorMacro) and leaves the model as it was.
  void SetModel(int model);
  vtkGetMacro(Model, int);
  /// By scene-file name; an unknown name is an error (vtkErrorMacro):
  /// false, and the model as it was.
  bool SetModelName(const char* name);
  ///@}

  ///@{
  /// Shading frequency: FLAT, GOURAUD or PHONG.
  void SetFrequency(int frequency);
  vtkGetMacro(Frequency, int);
  /// By name ("flat", "gouraud", "phong"); another name is an error
  /// (vtkErrorMacro): false, and the frequency as it was.
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
  /// The light the component view shows: -1 for all lights (N.L shows light 0);
  /// clamped to [-1, GetMaximumNumberOfLights() - 1].
  void SetComponentLight(int light);
  vtkGetMacro(ComponentLight, int);
  ///@}

  ///@{
  /// Show components in false colour instead of grey/RGB.
  vtkSetMacro(FalseColor, bool);
  vtkGetMacro(FalseColor, bool);
  vtkBooleanMacro(FalseColor, bool);
  ///@}

  ///@{
  /// A BRDF Explorer .brdf file shading in place of the model's diffuse and
  /// specular factors, its parameters at their defaults. False, after
  /// vtkErrorMacro ("FILE:LINE: reason"), for a file that cannot be read or
  /// parsed; the pass then keeps its BRDF. SetBrdfText() parses @p text as
  /// a file named @p path (for messages). RemoveBrdf(): the model again.
  bool LoadBrdfFile(const char* path);
  bool SetBrdfText(const char* text, const char* path);
  void RemoveBrdf();
  bool HasBrdf() const;
  /// The .brdf file's path ("" without one).
  const char* GetBrdfFileName() const;
  ///@}

  /// Kinds of .brdf parameters.
  enum BrdfParameterKind
  {
    BRDF_FLOAT = 0,
    BRDF_BOOL = 1,
    BRDF_COLOR = 2
  };

  ///@{
  /// The .brdf file's parameters, in the file's order: name, kind, range
  /// (floats), default and current value (floats and bools in the first
  /// component, 0 or 1 for bools; colours RGB).
  int GetNumberOfBrdfParameters() const;
  const char* GetBrdfParameterName(int i) const;
  int GetBrdfParameterKind(int i) const;
  double GetBrdfParameterMinimum(int i) const;
  double GetBrdfParameterMaximum(int i) const;
  void GetBrdfParameterDefault(int i, double value[3]) const;
  void GetBrdfParameterValue(int i, double value[3]) const;
  ///@}

  ///@{
  /// Sets parameters as `shadelab render --param` does: "name=value", a
  /// bool true/false/0/1, a colour "r,g,b", a float within its range.
  /// False, after vtkErrorMacro, for an unknown name or a bad value (the
  /// values are then unchanged). A uniform: no shader is rebuilt.
  bool SetBrdfParameter(const char* assignment);
  /// The same for a float or bool (0 or 1) @p name.
  bool SetBrdfParameter(const char* name, double value);
  /// The same for a colour @p name.
  bool SetBrdfParameter(const char* name, double r, double g, double b);
  ///@}

  /// The one-line problem of the .brdf BRDF: its GLSL's compile error
  /// ("FILE:LINE: driver message"), or why the scene's .brdf file could not
  /// be used; "" when there is none (or the BRDF was not yet drawn).
  const char* GetBrdfError() const;

  /// How many times the pass has written its code into a mapper's shaders
  /// (shader variants built); uniform changes leave it alone.
  int GetNumberOfShaderBuilds() const;

#ifndef __VTK_WRAP__
  /// The C++ form of LoadBrdfFile(): @p file as read by shadelab::readBrdfFile
  /// and the values of its parameters (shadelab::brdfParameterValues).
  void SetBrdf(const shadelab::BrdfFile& file, const std::vector<glm::vec3>& values);
#endif

  /// The most lights the shaders hold (the one place this number lives:
  /// slLightingPassShaders.h). A scene or renderer with more is drawn with
  /// the first GetMaximumNumberOfLights() only, after a vtkErrorMacro (see
  /// the caveat above); check with GetLightCountProblem() first.
  static int GetMaximumNumberOfLights();

  /// "" if the pass draws all of @p numberOfLights lights; else the one-line
  /// problem ("17 lights; ShadeLab's lighting pass draws at most 16").
  static std::string GetLightCountProblem(int numberOfLights);

  /// Lights used in the last frame (after camera-light transforms).
  int GetNumberOfLightsUsed() const;

  void Render(const vtkRenderState* s) override;
  /// Also gives the actors their interpolation back (see the caveat above).
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
  /// Gives each property MatchInterpolation() changed its user's
  /// interpolation back, where it still has the pass's.
  void RestoreInterpolations();
  /// Watches @p renderer, drawn through the pass, for a change of its pass
  /// (RendererModified() then gives the interpolations back).
  void WatchRenderer(vtkRenderer* renderer);
  void RendererModified(vtkObject* renderer, unsigned long event, void* data);
  void MapTangents(const vtkRenderState* s);
  bool SetBrdfValues(const std::vector<std::string>& assignments);
  void SetBrdfFromScene();
  bool CheckBrdf(const std::string& brdfSource);

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
