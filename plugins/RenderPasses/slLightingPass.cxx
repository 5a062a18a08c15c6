#include "slLightingPass.h"

#include "slLightingPassInternals.h"
#include "slLightingPassQueries.h"
#include "slLightingPassShaders.h"
#include "slLightingPassUniforms.h"
#include "slModelCheck.h"
#include "slScene.h"

#include "shadelab/BrdfFile.h"
#include "shadelab/LightingGLSL.h"
#include "shadelab/Scene.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkDataObject.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkProp.h>
#include <vtkProperty.h>
#include <vtkRenderState.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkShader.h>
#include <vtkShaderProgram.h>

#include <algorithm>
#include <utility>
#include <vector>

// The pass's lights, shaders and uniforms. Its .brdf file API is in
// slLightingPassBrdf.cxx, the actors' interpolation in
// slLightingPassInterpolation.cxx (slLightingPassInternals.h: the state they share).
vtkStandardNewMacro(slLightingPass);

namespace shaders = slLightingPassShaders;
using namespace slLightingPassQueries;
using namespace slLightingPassUniforms;
using slLightingPassInterpolation::DrawnRenderer;

namespace
{
const char* const kLightTag = "//SL::Light::Impl";
const char* const kTextureTag = "//SL::TCoord::Impl";
const char* const kDeclarationTag = "//SL::Light::Dec";
} // namespace

const ProgramFacts& slLightingPass::Internals::FactsOf(vtkShaderProgram* program)
{
  if (const ProgramFacts* known = this->Programs.Find(program))
  {
    return *known;
  }
  const std::string& source = program->GetFragmentShader()->GetSource();
  ProgramFacts facts;
  facts.scalarColours = drawsScalarColours(source);
  facts.backface = shaders::hasBackfaceMaterial(source);
  return this->Programs.Insert(program, facts);
}

slLightingPass::slLightingPass()
  : DelegatePass(vtkSmartPointer<vtkRenderStepsPass>::New())
  , Internal(new Internals)
{
  for (int i = 0; i < shaders::MaximumLights; ++i)
  {
    this->Internal->Names.emplace_back(i);
  }
  this->ShaderStageTime.Modified();
}

slLightingPass::~slLightingPass()
{
  // VTK's mappers hold the passes they last drew with until they draw again,
  // so the pass is often freed in the middle of a frame, inside a mapper:
  // the interpolations are then given back once the frame is drawn.
  vtkRenderWindow* drawing = nullptr;
  this->Internal->Renderers.ForEachLive([&drawing](vtkRenderer* renderer, const DrawnRenderer& drawn) {
    renderer->RemoveObserver(drawn.observer);
    vtkRenderWindow* window = renderer->GetRenderWindow();
    drawing = window && window->CheckInRenderStatus() ? window : drawing;
  });
  if (drawing)
  {
    slLightingPassInterpolation::restoreAfterFrame(drawing, std::move(this->Internal->Interpolations));
  }
  else
  {
    this->RestoreInterpolations();
  }
}

int slLightingPass::GetMaximumNumberOfLights()
{
  return shaders::MaximumLights;
}

std::string slLightingPass::GetLightCountProblem(int numberOfLights)
{
  if (numberOfLights <= shaders::MaximumLights)
  {
    return "";
  }
  return std::to_string(numberOfLights) + " lights; ShadeLab's lighting pass draws at most " +
    std::to_string(shaders::MaximumLights);
}

void slLightingPass::SetComponentLight(int light)
{
  light = std::max(-1, std::min(light, shaders::MaximumLights - 1));
  if (light != this->ComponentLight)
  {
    this->ComponentLight = light;
    this->Modified();
  }
}

int slLightingPass::GetNumberOfLightsUsed() const
{
  return static_cast<int>(this->Internal->LightsVC.size());
}

void slLightingPass::SetDelegatePass(vtkRenderPass* delegate)
{
  if (delegate != this->DelegatePass)
  {
    this->DelegatePass = delegate;
    this->Modified();
  }
}

vtkRenderPass* slLightingPass::GetDelegatePass()
{
  return this->DelegatePass;
}

void slLightingPass::SetScene(slScene* scene)
{
  if (scene != this->Scene)
  {
    this->Scene = scene;
    this->Modified();
  }
  // Copied again for the same scene too (it may have been edited); each
  // setter marks the pass modified only for a real change.
  if (scene)
  {
    this->SetModel(static_cast<int>(scene->GetScene().model));
    this->SetFrequency(static_cast<int>(scene->GetScene().frequency));
    this->SetBrdfFromScene();
  }
}

slScene* slLightingPass::GetScene()
{
  return this->Scene;
}

void slLightingPass::SetModel(int model)
{
  if (slCheckModel(this, model) && model != this->Model)
  {
    this->Model = model;
    this->ShaderStageTime.Modified(); // compiled into the shaders: model tests fold away
    this->Modified();
  }
}

bool slLightingPass::SetModelName(const char* name)
{
  return slSetModelByName(this, name);
}

void slLightingPass::SetFrequency(int frequency)
{
  frequency = frequency < FLAT ? FLAT : (frequency > PHONG ? PHONG : frequency);
  if (frequency != this->Frequency)
  {
    this->Frequency = frequency;
    this->ShaderStageTime.Modified(); // compiled into the shaders, as the model and the lights' types are
    this->Modified();
  }
}

void slLightingPass::SetComponent(int component)
{
  component = component < TOTAL ? TOTAL : (component > COS_THETA ? COS_THETA : component);
  if (component != this->Component)
  {
    if ((component == TOTAL) != (this->Component == TOTAL))
    {
      this->ShaderStageTime.Modified(); // a component view is compiled in or out
    }
    this->Component = component;
    this->Modified();
  }
}

bool slLightingPass::SetFrequencyName(const char* name)
{
  shadelab::ShadingFrequency frequency;
  if (!name || !shadelab::parseFrequencyName(name, frequency))
  {
    vtkErrorMacro(<< "SetFrequencyName: " << shadelab::frequencyNameProblem(name));
    return false;
  }
  this->SetFrequency(static_cast<int>(frequency));
  return true;
}

int slLightingPass::GetNumberOfShaderBuilds() const
{
  return this->Internal->ShaderBuilds;
}

vtkMTimeType slLightingPass::GetShaderStageMTime()
{
  return this->ShaderStageTime.GetMTime();
}

void slLightingPass::PrepareLights(vtkRenderer* renderer)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  std::vector<shadelab::SceneLight> lights;
  if (this->Scene)
  {
    lights = this->Scene->GetScene().lights;
  }
  else
  {
    vtkNew<slScene> fromVTK;
    fromVTK->SetLightsFromVTK(renderer->GetLights());
    lights = fromVTK->GetScene().lights;
  }
  // Too many lights: an error (the picture lacks some), reported once until
  // the lights fit again; the first ones are still drawn.
  const std::string tooMany = GetLightCountProblem(static_cast<int>(std::min<size_t>(lights.size(), VTK_INT_MAX)));
  if (!tooMany.empty())
  {
    if (!this->Internal->ReportedTooManyLights)
    {
      vtkErrorMacro(<< tooMany << ": the others are left out of the picture");
      this->Internal->ReportedTooManyLights = true;
    }
    lights.resize(shaders::MaximumLights);
  }
  else
  {
    this->Internal->ReportedTooManyLights = false;
  }

  const glm::vec3 eye = toVec3(camera->GetPosition());
  const glm::vec3 focal = toVec3(camera->GetFocalPoint());
  const glm::vec3 up = toVec3(camera->GetViewUp());
  vtkMatrix4x4* view = camera->GetModelViewTransformMatrix();
  auto transformPoint = [view](const glm::vec3& p) {
    const double in[4] = { p.x, p.y, p.z, 1.0 };
    double out[4];
    view->MultiplyPoint(in, out);
    return glm::vec3(static_cast<float>(out[0]), static_cast<float>(out[1]), static_cast<float>(out[2]));
  };
  auto transformDirection = [view](const glm::vec3& d) {
    const double in[4] = { d.x, d.y, d.z, 0.0 };
    double out[4];
    view->MultiplyPoint(in, out);
    return shadelab::glsl::slSafeNormalize(
      glm::vec3(static_cast<float>(out[0]), static_cast<float>(out[1]), static_cast<float>(out[2])));
  };

  const std::vector<int> previousTypes = this->Internal->LightTypes();
  this->Internal->LightsVC.clear();
  for (const shadelab::SceneLight& light : lights)
  {
    shadelab::glsl::slLight l = shadelab::toEvaluationLight(shadelab::lightInWorldSpace(light, eye, focal, up));
    l.position = transformPoint(l.position);
    l.direction = transformDirection(l.direction);
    this->Internal->LightsVC.push_back(l);
  }
  this->Internal->Parallel = camera->GetParallelProjection() != 0;
  if (this->Internal->LightTypes() != previousTypes)
  {
    this->ShaderStageTime.Modified(); // light count and types are compiled into the shaders
  }
}

void slLightingPass::MapTangents(const vtkRenderState* s)
{
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkActor* actor = vtkActor::SafeDownCast(s->GetPropArray()[i]);
    auto* mapper = actor ? vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper()) : nullptr;
    if (!mapper || !hasTangentsWithHandedness(mapper))
    {
      continue;
    }
    if (!this->Internal->TangentMappers.Find(mapper))
    {
      // Once per mapper: mapping an attribute marks the mapper modified.
      mapper->MapDataArrayToVertexAttribute("slTangentMC", "Tangents", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
      this->Internal->TangentMappers.Insert(mapper, true);
    }
  }
}

void slLightingPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro(<< "no delegate pass");
    return;
  }
  vtkRenderer* renderer = s->GetRenderer();
  auto anyLightOn = [renderer] {
    vtkLightCollection* lights = renderer->GetLights();
    lights->InitTraversal();
    while (vtkLight* light = lights->GetNextItem())
    {
      if (light->GetSwitch())
      {
        return true;
      }
    }
    return false;
  };
  // With no light switched on VTK adds a headlight (AutomaticLightCreation,
  // vtkOpenGLRenderer::UpdateLights), after the pass has read the lights:
  // add it first, so that the renderer's lights light the picture as without
  // the pass (a scene's lights leave the renderer's alone).
  if (!this->Scene && !anyLightOn() && renderer->GetAutomaticLightCreation())
  {
    renderer->CreateLight();
  }
  this->PrepareLights(renderer);
  this->WatchRenderer(renderer);
  this->MatchInterpolation(s);
  this->MapTangents(s);

  // Without a light switched on, VTK's mapper draws unlit and passes no
  // normals: so does the pass with the renderer's lights, but the scene's
  // lights need the normals.
  vtkSmartPointer<vtkLight> placeholder;
  if (this->Scene && !anyLightOn())
  {
    placeholder = vtkSmartPointer<vtkLight>::New();
    placeholder->SetLightTypeToHeadlight();
    placeholder->SetIntensity(0.0);
    renderer->AddLight(placeholder);
  }

  this->PreRender(s);
  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();
  this->PostRender(s);

  if (placeholder)
  {
    renderer->RemoveLight(placeholder);
  }
}

void slLightingPass::ReleaseGraphicsResources(vtkWindow* window)
{
  // VTK calls this when the renderer leaves its window (RemoveRenderer,
  // SetRenderWindow) and when the window is finalised, not while frames are
  // drawn: the actors' shaders go with the resources, and a next frame
  // through the pass sets the interpolation again before anything is drawn.
  this->RestoreInterpolations();
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(window);
  }
}

bool slLightingPass::PreReplaceShaderValues(
  std::string& vertexShader, std::string&, std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop)
{
  if (isOurs(mapper, prop))
  {
    // Mark where our declarations go (VTK consumes its own tags), and keep
    // VTK from writing its own lighting and texture modulation; our code goes
    // in these places in PostReplaceShaderValues().
    const std::string declarations = std::string(kDeclarationTag) + "\n//VTK::Light::Dec";
    vtkShaderProgram::Substitute(vertexShader, "//VTK::Light::Dec", declarations, false);
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Dec", declarations, false);
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Impl", kLightTag, false);
    if (hasTangentsWithHandedness(mapper))
    {
      vtkShaderProgram::Substitute(vertexShader, "//VTK::Light::Dec", "//SL::Tangent::Dec\n//VTK::Light::Dec", false);
      vtkShaderProgram::Substitute(vertexShader, "//VTK::Light::Impl", "//SL::Tangent::Impl\n//VTK::Light::Impl", false);
    }
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::TCoord::Impl", kTextureTag, false);
  }
  return true;
}

bool slLightingPass::PostReplaceShaderValues(std::string& vertexShader, std::string&,
  std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  if (!contains(fragmentShader, kLightTag))
  {
    return true;
  }

  // VTK lights lines and points only with point normals and smooth
  // interpolation, and passes the view-coordinate position only to what it
  // lights; the rest it draws in the ambient + diffuse colour, and so does
  // the pass.
  if (!contains(vertexShader, "vertexVCVSOutput"))
  {
    for (std::string* shader : { &vertexShader, &fragmentShader })
    {
      for (const char* tag : { kDeclarationTag, "//SL::Tangent::Dec", "//SL::Tangent::Impl", kTextureTag })
      {
        vtkShaderProgram::Substitute(*shader, tag, "", false);
      }
    }
    vtkShaderProgram::Substitute(fragmentShader, kLightTag,
      shaders::unlitFragmentImplementation(hasActorTexture(fragmentShader), textureFrontOnly(prop)), false);
    return true;
  }

  // vtkShadowMapPass scales VTK's own per-light terms, which the pass's
  // lighting replaces: say once that the shadows are missing.
  if (contains(fragmentShader, "uniform sampler2D shadowMap") && !this->Internal->WarnedShadows)
  {
    vtkWarningMacro(<< "shadows (vtkShadowMapPass) are not drawn: ShadeLab's lighting replaces VTK's");
    this->Internal->WarnedShadows = true;
  }

  auto frequency = static_cast<shaders::Frequency>(this->Frequency);
  const bool vertexNormals = contains(vertexShader, "out vec3 normalVCVSOutput");
  if (frequency != shaders::Flat && !vertexNormals)
  {
    if (!this->Internal->WarnedNoNormals)
    {
      vtkWarningMacro(<< "a mesh without point normals is shaded flat (Gouraud and Phong need point normals)");
      this->Internal->WarnedNoNormals = true;
    }
    frequency = shaders::Flat;
  }
  ++this->Internal->ShaderBuilds;
  shaders::Variant variant;
  variant.frequency = frequency;
  variant.lightTypes = this->Internal->LightTypes();
  variant.model = this->Model;
  variant.componentView = this->Component != TOTAL;
  variant.brdf = this->Internal->BrdfSource;
  shaders::FragmentInputs inputs;
  inputs.scalarColors = drawsScalarColours(fragmentShader);
  // As VTK, which reads a backface property only where the property's own
  // colours colour the surface (not under shown scalars). Actors without
  // one get shaders without a trace of it.
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  variant.backface = actor && actor->GetBackfaceProperty() && !inputs.scalarColors;
  // A BRDF whose GLSL does not compile is reported once, in one line
  // (GetBrdfError()); the mesh is drawn with the model meanwhile, so that
  // VTK's compile of the whole shader does not fail as well.
  if (!variant.brdf.empty() && !this->CheckBrdf(shaders::brdfCheckShader(variant)))
  {
    variant.brdf.clear();
  }
  inputs.texture = hasActorTexture(fragmentShader);
  variant.textureFrontOnly = inputs.texture && textureFrontOnly(prop);
  inputs.mapperFaceNormal = !vertexNormals && contains(fragmentShader, "normalVCVSOutput");
  // VTK maps normals itself only for 3-component tangents; 4-component
  // (MikkTSpace) ones reach the shader as slTangentMC, mapped in Render().
  const bool meshTangents = contains(vertexShader, "//SL::Tangent");
  inputs.tangentNormalMap = frequency == shaders::Phong && contains(fragmentShader, "sampler2D normalTex") &&
    contains(fragmentShader, "tcoordVCVSOutput") && !contains(fragmentShader, "tangentVCVSOutput") && meshTangents;
  const bool anisotropic = shadelab::modelNeedsTangents(static_cast<shadelab::ShadingModel>(this->Model));
  // A .brdf file's BRDF frame takes the mesh's tangents too (without them, a
  // frame built from the normal, as for an anisotropic model).
  const bool brdf = !variant.brdf.empty();
  inputs.surfaceTangent = meshTangents && (inputs.tangentNormalMap || anisotropic || brdf);
  if (anisotropic && !brdf && !meshTangents && !this->Internal->WarnedNoTangents)
  {
    vtkErrorMacro(<< "the " << shadelab::modelName(static_cast<shadelab::ShadingModel>(this->Model))
                  << " model is anisotropic and needs the mesh's tangents (a 4-component point array \"Tangents\", "
                     "from slPolyDataTangents); without them it is drawn in a fixed frame around the normal");
    this->Internal->WarnedNoTangents = true;
  }
  if (inputs.surfaceTangent)
  {
    // VTK declares normalMatrix only with vertex normals, which flat shading
    // goes without; the tangents need it (VTK sets it whenever it is used).
    const std::string normalMatrix =
      contains(vertexShader, "uniform mat3 normalMatrix") ? "" : "uniform mat3 normalMatrix;\n";
    vtkShaderProgram::Substitute(
      vertexShader, "//SL::Tangent::Dec", normalMatrix + shaders::tangentVertexDeclarations(frequency), false);
    vtkShaderProgram::Substitute(vertexShader, "//SL::Tangent::Impl", shaders::tangentVertexImplementation(), false);
  }

  vtkShaderProgram::Substitute(vertexShader, kDeclarationTag, shaders::vertexDeclarations(variant), false);
  vtkShaderProgram::Substitute(vertexShader, "//VTK::Light::Impl",
    shaders::vertexImplementation(variant, inputs.surfaceTangent) + "//VTK::Light::Impl", false);
  vtkShaderProgram::Substitute(
    fragmentShader, kDeclarationTag, shaders::fragmentDeclarations(variant, inputs), false);
  vtkShaderProgram::Substitute(fragmentShader, kLightTag, shaders::fragmentImplementation(variant, inputs), false);
  vtkShaderProgram::Substitute(fragmentShader, kTextureTag, "", false);
  return true;
}

bool slLightingPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  if (!program->IsUniformUsed("slComponent") && !program->IsUniformUsed("slMat.emission"))
  {
    return true; // not one of our shaders, or everything was optimised away
  }
  Internals& in = *this->Internal;
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  vtkProperty* backProperty = actor ? actor->GetBackfaceProperty() : nullptr;
  const bool sceneMaterial = this->UseSceneMaterial && this->Scene;
  // What the program is matters only for the property's material (scalar
  // colours) and for an actor with a backface property (whether its shaders
  // were built for one); for the others it is not looked up.
  const ProgramFacts* facts = !sceneMaterial || backProperty ? &in.FactsOf(program) : nullptr;
  shadelab::glsl::slMaterial m;
  if (sceneMaterial)
  {
    m = shadelab::toEvaluationMaterial(this->Scene->GetScene().material);
  }
  else
  {
    m = actor ? materialOf(actor->GetProperty()) : shadelab::toEvaluationMaterial(shadelab::SceneMaterial());
    if (actor && facts->scalarColours)
    {
      // As in VTK, the scalar colour (the shader's base colour) takes the
      // place of the property's ambient and diffuse colours.
      m.ambient = glm::vec3(static_cast<float>(actor->GetProperty()->GetAmbient()));
      m.diffuse = glm::vec3(static_cast<float>(actor->GetProperty()->GetDiffuse()));
    }
  }
  // Each light with this actor's k_a, k_d, k_s folded in (slFoldLight), as
  // the CPU kernel folds them; the shader shades with slUnitMaterial(slMat).
  // A .brdf file's BRDF takes k_d's place: the lights are folded with k_d = 1.
  const bool brdf = in.Brdf && in.BrdfError.empty();
  auto folding = [brdf](shadelab::glsl::slMaterial k) {
    if (brdf)
    {
      k.diffuse = glm::vec3(1.0f);
    }
    return k;
  };
  if (brdf)
  {
    setBrdfUniforms(program, *in.Brdf, in.BrdfValues);
  }
  const std::vector<shadelab::glsl::slLight>& lights = in.LightsVC;
  if (actor && facts && facts->backface)
  {
    // Shaders with a backface material: k_a, k_d, k_s differ by side, so
    // the lights carry only their intensity and the shader multiplies each
    // side's coefficients into the sums (slLightAll). Both sides take the
    // scene's material when it is used, and the front's when the backface
    // property was taken away after the shaders were built (VTK rebuilds
    // them only after a change to the actor's own property).
    vtkProperty* backSide = backProperty ? backProperty : actor->GetProperty();
    const shadelab::glsl::slMaterial front = folding(m);
    const shadelab::glsl::slMaterial back = folding(sceneMaterial || !backProperty ? m : materialOf(backProperty));
    const shadelab::glsl::slMaterial intensityOnly = shadelab::glsl::slUnitMaterial(front);
    for (size_t i = 0; i < lights.size(); ++i)
    {
      setLightUniforms(program, in.Names[i], shadelab::glsl::slFoldLight(lights[i], intensityOnly));
    }
    setMaterialUniforms(program, in.FrontMaterialNames, front);
    setMaterialUniforms(program, in.BackMaterialNames, back);
    // VTK's colour code gives faces seen from behind this opacity, but VTK
    // sets it only with the backface colours, which the pass's lighting
    // leaves unused (so the compiler drops them).
    program->SetUniformf("opacityUniformBF", static_cast<float>(backSide->GetOpacity()));
  }
  else
  {
    const shadelab::glsl::slMaterial folded = folding(m);
    for (size_t i = 0; i < lights.size(); ++i)
    {
      setLightUniforms(program, in.Names[i], shadelab::glsl::slFoldLight(lights[i], folded));
    }
    setMaterialUniforms(program, in.FrontMaterialNames, m);
  }
  program->SetUniformi("slComponent", this->Component);
  program->SetUniformi("slComponentLight", this->ComponentLight);
  program->SetUniformi("slFalseColor", this->FalseColor ? 1 : 0);
  program->SetUniformi("slParallel", in.Parallel ? 1 : 0);
  program->SetUniformf("slNormalScale", actor ? static_cast<float>(actor->GetProperty()->GetNormalScale()) : 1.0f);
  return true;
}

void slLightingPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Model: " << shadelab::modelName(static_cast<shadelab::ShadingModel>(this->Model)) << "\n";
  os << indent << "Frequency: " << shadelab::frequencyName(static_cast<shadelab::ShadingFrequency>(this->Frequency))
     << "\n";
  os << indent << "UseSceneMaterial: " << this->UseSceneMaterial << "\n";
  os << indent << "Component: " << this->Component << "\n";
  os << indent << "ComponentLight: " << this->ComponentLight << "\n";
  os << indent << "FalseColor: " << this->FalseColor << "\n";
  os << indent << "Brdf: " << (this->Internal->Brdf ? this->Internal->Brdf->path : "(none: the model)") << "\n";
  for (int i = 0; i < this->GetNumberOfBrdfParameters(); ++i)
  {
    double value[3];
    this->GetBrdfParameterValue(i, value);
    os << indent.GetNextIndent() << this->GetBrdfParameterName(i) << ": " << value[0];
    if (this->GetBrdfParameterKind(i) == BRDF_COLOR)
    {
      os << " " << value[1] << " " << value[2];
    }
    os << "\n";
  }
  os << indent << "BrdfError: " << this->Internal->BrdfError << "\n";
  os << indent << "Scene: " << (this->Scene ? "set" : "(none: the renderer's lights)") << "\n";
  os << indent << "DelegatePass: " << this->DelegatePass.GetPointer() << "\n";
  os << indent << "NumberOfLightsUsed: " << this->GetNumberOfLightsUsed() << "\n";
  os << indent << "NumberOfShaderBuilds: " << this->GetNumberOfShaderBuilds() << "\n";
  // What the pass keeps per mapper and shader program it has seen (entries
  // of freed ones are dropped as the records grow).
  os << indent << "TrackedMappers: " << this->Internal->TangentMappers.Size() << "\n";
  os << indent << "TrackedShaderPrograms: " << this->Internal->Programs.Size() << "\n";
  os << indent << "TrackedProperties: " << this->Internal->Interpolations.Size() << "\n";
  os << indent << "TrackedRenderers: " << this->Internal->Renderers.Size() << "\n";
}
