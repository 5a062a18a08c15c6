#ifndef slLitFilter_h
#define slLitFilter_h
/**
 * @class   slLitFilter
 * @brief   Base of the ShadeLab filters that light a mesh: where the lights,
 *          material, lighting model and eye come from, and the input checks
 *          they share.
 *
 * The lighting comes from an slScene (SetScene(); ShadeLab's default scene
 * when none is set) and/or VTK's own objects: SetLights() takes a renderer's
 * vtkLightCollection, SetProperty() a vtkProperty for the material and
 * SetCamera() a vtkCamera for the eye. Each VTK object that is set replaces
 * the corresponding part of the scene, converted by slScene (so a VTK user's
 * existing lights just work, camera and headlights included). A scene camera
 * without a position is fitted to the input's bounds as slScene::ApplyCamera()
 * does, to the bounds of the whole input: under MPI (VTK's global
 * vtkMultiProcessController with more than one process, as in ParaView's
 * pvbatch and pvserver) the bounds are united over all ranks, so the eye,
 * and with it every view-dependent value, is the same on any number of
 * ranks as on one.
 *
 * For ParaView, whose client-server wrapping reaches only plain values and
 * vtk* objects, the scene can also come from a file (SetSceneFileName(),
 * read at every update; it replaces SetScene()), the lighting model can be
 * chosen with SetModel() and, with OverrideMaterial on, the material's
 * colours and numbers with plain setters. Numbers are clamped to the
 * material table's ranges (docs/scene-format.md); colours out of range are
 * errors, as in a scene file.
 *
 * Input checks, each giving vtkErrorMacro of one line, an empty output and
 * a failed request (slUpdateOrThrow() gives the line back): an input without points, without point
 * normals, with a zero-length or non-finite point normal (unless
 * ZeroNormalsAreErrors is off: such points then get no direction-dependent
 * light), and a scene without lights where the subclass needs one (named by
 * its file when it was read from one). Messages about the input begin with
 * "input mesh:" so that callers can put the file name in its place.
 *
 * @warning Subclasses never restate a lighting formula: they evaluate
 * slLighting.glsl through shadelab/LightingGLSL.h.
 *
 * @sa slScene slRadianceFilter slCosineField slLobesOnMesh slRadianceReference
 */

#include "ShadeLabLightingModule.h"
#include "slMaterialNumberAccessors.h" // the material numbers

#include <vtkPolyDataAlgorithm.h>

#include <string>

class slScene;
class vtkCamera;
class vtkLightCollection;
class vtkProperty;

#ifndef __VTK_WRAP__
namespace shadelab
{
struct LightingSetup;
}
#endif

class SHADELABLIGHTING_EXPORT slLitFilter : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(slLitFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Whether @p mesh carries the tangents the anisotropic models read
  /// (shadelab::modelNeedsTangents()): a 4-component point array "Tangents"
  /// with one tuple per point, as slPolyDataTangents makes it.
  static bool HasTangents(vtkPolyData* mesh);

  ///@{
  /// The scene: lights, material, model and camera. Null: the default scene.
  virtual void SetScene(slScene* scene);
  vtkGetObjectMacro(Scene, slScene);
  ///@}

  ///@{
  /// VTK's own lights (e.g. renderer->GetLights()); replace the scene's lights.
  virtual void SetLights(vtkLightCollection* lights);
  vtkGetObjectMacro(Lights, vtkLightCollection);
  ///@}

  ///@{
  /// A vtkProperty that replaces the scene's material.
  virtual void SetProperty(vtkProperty* property);
  vtkGetObjectMacro(Property, vtkProperty);
  ///@}

  ///@{
  /// A vtkCamera whose position is the eye (and which places camera lights).
  virtual void SetCamera(vtkCamera* camera);
  vtkGetObjectMacro(Camera, vtkCamera);
  ///@}

  ///@{
  /// A JSON scene file read at each update in place of SetScene(); "" or
  /// null (default): SetScene()'s scene. A file that cannot be read is an
  /// error naming the file.
  vtkSetStringMacro(SceneFileName);
  vtkGetStringMacro(SceneFileName);
  ///@}

  ///@{
  /// The lighting model (an SL_MODEL_* value, a row of
  /// shadelab/LightingTables.h, as in slBRDFLobeSource), or -1 (default) for
  /// the scene's own. Any other value is an error (vtkErrorMacro) and leaves
  /// the model as it was.
  void SetModel(int model);
  vtkGetMacro(Model, int);
  /// By scene-file name ("phong", "cook-torrance-ggx", ...: those of
  /// slScene::SetModelName()); an unknown name is an error (vtkErrorMacro):
  /// false, and the model as it was. GetModelName() is "" while the model
  /// is the scene's own.
  bool SetModelName(const char* name);
  std::string GetModelName() const;
  ///@}

  ///@{
  /// Whether the material values below replace the scene's (after
  /// SetProperty(), if any). Off by default.
  vtkSetMacro(OverrideMaterial, bool);
  vtkGetMacro(OverrideMaterial, bool);
  vtkBooleanMacro(OverrideMaterial, bool);
  ///@}

  ///@{
  /// Material colours k_a, k_d, k_s, k_e (linear RGB, [0, 1e6]); used when
  /// OverrideMaterial is on. Defaults: the default scene's (0.1, 0.8, 0.5
  /// and 0). A colour out of range is an error at the next update, as in a
  /// scene file.
  vtkSetVector3Macro(AmbientColor, double);
  vtkGetVector3Macro(AmbientColor, double);
  vtkSetVector3Macro(DiffuseColor, double);
  vtkGetVector3Macro(DiffuseColor, double);
  vtkSetVector3Macro(SpecularColor, double);
  vtkGetVector3Macro(SpecularColor, double);
  vtkSetVector3Macro(EmissionColor, double);
  vtkGetVector3Macro(EmissionColor, double);
  ///@}

  ///@{
  /// The material's numbers, one per number row of the material table
  /// (shadelab/LightingTables.h, docs/scene-format.md), used when
  /// OverrideMaterial is on and clamped to the row's range: shininess n
  /// ([0, 1e5], Phong and Blinn-Phong), roughness alpha ([0, 1], GGX,
  /// Beckmann, Oren-Nayar), the anisotropic pair RoughnessX along the
  /// tangent and RoughnessY along N x tangent ([0, 1] each, Ward,
  /// Ashikhmin-Shirley) and the index of refraction ([1, 10], Schlick's
  /// Fresnel). Defaults: the default scene's (32, 0.3, 0.15, 0.45, 1.5). A
  /// NaN is kept, and is an error at the next update.
  vtkSetClampMacro(Shininess, double, shadelab::materialRows::shininess.lo, shadelab::materialRows::shininess.hi);
  vtkGetMacro(Shininess, double);
  slMaterialNumberAccessorsMacro()
  ///@}

  ///@{
  /// Whether a zero-length or non-finite point normal is an error (default)
  /// or lit as "no direction" (ambient and emission only, CosTheta 0).
  vtkSetMacro(ZeroNormalsAreErrors, bool);
  vtkGetMacro(ZeroNormalsAreErrors, bool);
  vtkBooleanMacro(ZeroNormalsAreErrors, bool);
  ///@}

  vtkMTimeType GetMTime() override;

  /// Runs the request; one that throws (std::bad_alloc: "input mesh: out of
  /// memory (in CLASS)") fails as a VTK error (slProcessRequestSafely()), so
  /// that the filter can run again on another input.
  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

protected:
  slLitFilter();
  ~slLitFilter() override;

#ifndef __VTK_WRAP__
  /// Checks @p input and gathers the lighting; on failure reports through
  /// Fail() (emptying @p output) and returns false. @p needLight: a scene
  /// without lights fails. @p checkNormals: look for normals without a
  /// direction here (when ZeroNormalsAreErrors is on); a filter that visits
  /// every normal anyway passes false and calls FailOnZeroNormal() itself.
  bool PrepareLighting(vtkPolyData* input, vtkPolyData* output, bool needLight, shadelab::LightingSetup& setup,
    bool checkNormals = true);
#endif

  /// The mesh's "Tangents" point array (4 components, as slPolyDataTangents
  /// makes them; the fourth, the handedness, is not read) if the model of @p setup is anisotropic
  /// (modelNeedsTangents()), else null. Sets @p tangents and returns true, or
  /// calls Fail() and returns false when the model needs tangents the mesh
  /// does not have.
  bool GetTangents(vtkPolyData* input, vtkPolyData* output, const shadelab::LightingSetup& setup,
    vtkDataArray*& tangents);

  /// Fail() for point @p point of @p points, whose normal has no direction.
  int FailOnZeroNormal(vtkPolyData* output, vtkIdType point, vtkIdType points);

  /// Reports @p message (one line) with vtkErrorMacro and empties @p output.
  /// Returns 0 for RequestData to return.
  int Fail(vtkPolyData* output, const std::string& message);

  /// Bounds of the whole input over all MPI ranks (xmin, xmax, ...), set by
  /// PrepareLighting(): sizes derived from them do not depend on the partition.
  double WholeBounds[6] = { 0, -1, 0, -1, 0, -1 };

  slScene* Scene = nullptr;
  vtkLightCollection* Lights = nullptr;
  vtkProperty* Property = nullptr;
  vtkCamera* Camera = nullptr;
  bool ZeroNormalsAreErrors = true;
  char* SceneFileName = nullptr;
  int Model = -1;
  bool OverrideMaterial = false;
  double AmbientColor[3];
  double DiffuseColor[3];
  double SpecularColor[3];
  double EmissionColor[3];
  double Shininess;
  slMaterialNumberMembersMacro()

private:
  slLitFilter(const slLitFilter&) = delete;
  void operator=(const slLitFilter&) = delete;
};

#endif
