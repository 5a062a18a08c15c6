#include "slLightingPass.h"

#include "slLightingPassShaders.h"
#include "slModelCheck.h"
#include "slScene.h"

#include "shadelab/BrdfAssignment.h"
#include "shadelab/BrdfFile.h"
#include "shadelab/Error.h"
#include "shadelab/LightingGLSL.h"
#include "shadelab/Scene.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkDataArray.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkProp.h>
#include <vtkProperty.h>
#include <vtkRenderState.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkShader.h>
#include <vtkShaderProgram.h>
#include <vtkWeakPointer.h>

#include <algorithm>
#include <iterator>
#include <map>
#include <vector>

vtkStandardNewMacro(slLightingPass);

namespace shaders = slLightingPassShaders;

namespace
{
const char* const kLightTag = "//SL::Light::Impl";
const char* const kTextureTag = "//SL::TCoord::Impl";
const char* const kDeclarationTag = "//SL::Light::Dec";

bool contains(const std::string& text, const char* what)
{
  return text.find(what) != std::string::npos;
}

glm::vec3 toVec3(const double v[3])
{
  return glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
}

/// The uniform names of light i's fields, in the order of
/// SHADELAB_LIGHT_FIELDS ("slLights[2].position", ...), made once.
struct LightUniformNames
{
  std::vector<std::string> fields;
  explicit LightUniformNames(int i)
  {
    const std::string base = "slLights[" + std::to_string(i) + "].";
#define SHADELAB_NAME(type, field, ...) fields.push_back(base + #field);
    SHADELAB_LIGHT_FIELDS(SHADELAB_NAME)
#undef SHADELAB_NAME
  }
};

/// The uniform names of a material's fields, in the order of
/// SHADELAB_MATERIAL_PARAMETERS ("slMat.ambient", ...), made once.
struct MaterialUniformNames
{
  std::vector<std::string> fields;
  explicit MaterialUniformNames(const std::string& uniform)
  {
#define SHADELAB_NAME(type, field, ...) fields.push_back(uniform + "." #field);
    SHADELAB_MATERIAL_PARAMETERS(SHADELAB_NAME)
#undef SHADELAB_NAME
  }
};

void setUniform(vtkShaderProgram* program, const std::string& name, const glm::vec3& value)
{
  program->SetUniform3f(name.c_str(), &value[0]);
}
void setUniform(vtkShaderProgram* program, const std::string& name, float value)
{
  program->SetUniformf(name.c_str(), value);
}
/// The light's type is compiled into the shaders (slLightTypeOf), not uploaded.
void setUniform(vtkShaderProgram*, const std::string&, int) {}

/// Every field of @p light as the uniforms named @p names.
void setLightUniforms(vtkShaderProgram* program, const LightUniformNames& names, const shadelab::glsl::slLight& light)
{
  size_t f = 0;
#define SHADELAB_UPLOAD(type, field, ...) setUniform(program, names.fields[f++], light.field);
  SHADELAB_LIGHT_FIELDS(SHADELAB_UPLOAD)
#undef SHADELAB_UPLOAD
}

/// Every field of @p m as the uniforms named @p names.
void setMaterialUniforms(
  vtkShaderProgram* program, const MaterialUniformNames& names, const shadelab::glsl::slMaterial& m)
{
  size_t f = 0;
#define SHADELAB_UPLOAD(type, field, ...) setUniform(program, names.fields[f++], m.field);
  SHADELAB_MATERIAL_PARAMETERS(SHADELAB_UPLOAD)
#undef SHADELAB_UPLOAD
}

/// The material of an actor's vtkProperty, as VTK's own lighting reads it;
/// the numbers VTK has no place for (roughness, ...) at their defaults.
shadelab::glsl::slMaterial materialOf(vtkProperty* p)
{
  shadelab::glsl::slMaterial m = shadelab::toEvaluationMaterial(shadelab::SceneMaterial());
  m.ambient = static_cast<float>(p->GetAmbient()) * toVec3(p->GetAmbientColor());
  m.diffuse = static_cast<float>(p->GetDiffuse()) * toVec3(p->GetDiffuseColor());
  m.specular = static_cast<float>(p->GetSpecular()) * toVec3(p->GetSpecularColor());
  m.emission = glm::vec3(0.0f);
  m.shininess = static_cast<float>(p->GetSpecularPower());
  return m;
}

/// True if the mapper draws a point array "Tangents" with 4 components (xyz,
/// handedness). VTK's TANGENTS attribute only takes 3 components, so the
/// array is found by name.
bool hasTangentsWithHandedness(vtkAbstractMapper* mapper)
{
  auto* polyMapper = vtkOpenGLPolyDataMapper::SafeDownCast(mapper);
  vtkPolyData* input = polyMapper ? polyMapper->GetInput() : nullptr;
  vtkDataArray* tangents = input ? input->GetPointData()->GetArray("Tangents") : nullptr;
  return tangents && tangents->GetNumberOfComponents() == 4;
}

/// Opaque actors whose property has lighting on. An actor whose property has
/// lighting off (colour-mapped fields, widget handles, glyphs in their own
/// colour) is drawn unlit by VTK, as without the pass, and a translucent one
/// with VTK's lighting.
bool isLitOpaqueActor(vtkActor* actor)
{
  return actor && actor->GetMapper() && !actor->HasTranslucentPolygonalGeometry() &&
    actor->GetProperty()->GetLighting();
}

/// The polydata the pass lights: isLitOpaqueActor's, drawn by an OpenGL polydata mapper.
bool isOurs(vtkAbstractMapper* mapper, vtkProp* prop)
{
  return vtkOpenGLPolyDataMapper::SafeDownCast(mapper) && isLitOpaqueActor(vtkActor::SafeDownCast(prop));
}

/// Whether VTK's fragment shader @p fragmentShader colours the surface with
/// point or cell scalars (a colour attribute, a colour texture map or a cell
/// colour buffer): then VTK's ambientColor and diffuseColor are the scalar
/// colour times the property's intensities, in place of its colours.
bool drawsScalarColours(const std::string& fragmentShader)
{
  return contains(fragmentShader, "vertexColorVSOutput") || contains(fragmentShader, "colortexture") ||
    contains(fragmentShader, "textureC");
}

/// Whether VTK's fragment shader @p fragmentShader samples the actor's
/// texture (vtkActor::SetTexture) at the mesh's texture coordinates.
bool hasActorTexture(const std::string& fragmentShader)
{
  return contains(fragmentShader, "actortexture") && contains(fragmentShader, "tcoordVCVSOutput");
}

/// Whether @p prop's texture colours only faces seen from the front
/// (vtkProperty::ShowTexturesOnBackfaceOff()). A change to it modifies the
/// property, which rebuilds the actor's shaders, so it can be compiled in.
bool textureFrontOnly(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  return actor && !actor->GetProperty()->GetShowTexturesOnBackface();
}

/// What the pass needs to know of a built shader program, read from its
/// fragment shader's source once (the source is fixed once compiled, and
/// copying it for every actor of every frame would cost in scenes of many
/// actors).
struct ProgramFacts
{
  bool scalarColours = false; ///< drawsScalarColours()
  bool backface = false;      ///< a Variant::backface program (slMatBack)
};

/// Values the pass keeps per object it does not own (mappers, shader
/// programs, properties, renderers), by address. An entry holds a weak
/// pointer to its object: once the object is freed, the entry is not found,
/// even by a new object at the same address. Entries of freed objects are
/// dropped when an insertion finds the map past twice its size after the
/// last sweep: a long-running program that makes and frees many actors
/// keeps it within about twice the number of live objects, at an amortised
/// constant cost per insertion.
template <typename Object, typename Value>
class WeakKeyedMap
{
public:
  /// The value of @p object, or null if it has none (or is not the object
  /// the entry at its address was made for).
  const Value* Find(Object* object) const
  {
    const auto entry = this->Entries.find(object);
    return entry != this->Entries.end() && entry->second.first == object ? &entry->second.second : nullptr;
  }

  /// Gives @p object the value @p value (in place of a freed object's).
  const Value& Insert(Object* object, const Value& value)
  {
    if (this->Entries.size() > 2 * this->SizeAfterSweep)
    {
      for (auto entry = this->Entries.begin(); entry != this->Entries.end();)
      {
        entry = entry->second.first ? std::next(entry) : this->Entries.erase(entry);
      }
      this->SizeAfterSweep = this->Entries.size();
    }
    auto& entry = this->Entries[object];
    entry = { object, value };
    return entry.second;
  }

  /// Calls @p f(object, value) for every entry whose object is alive.
  template <typename Function>
  void ForEachLive(Function f) const
  {
    for (const auto& entry : this->Entries)
    {
      if (Object* object = entry.second.first.GetPointer())
      {
        f(object, entry.second.second);
      }
    }
  }

  void Clear()
  {
    this->Entries.clear();
    this->SizeAfterSweep = 0;
  }

  size_t Size() const { return this->Entries.size(); }

private:
  std::map<Object*, std::pair<vtkWeakPointer<Object>, Value>> Entries;
  size_t SizeAfterSweep = 0;
};

/// A property's interpolation as the pass found it (the user's) and as the
/// pass set it (MatchInterpolation), to give the user's back.
struct InterpolationChange
{
  int found = VTK_PHONG;
  int set = VTK_PHONG;
};

/// The interpolation a property of interpolation @p given needs for the
/// pass's @p frequency: VTK's mapper supplies face normals under flat
/// interpolation and interpolated point normals under any other, so flat
/// for FLAT, and for GOURAUD and PHONG the user's own unless it is flat
/// (then Phong).
int interpolationFor(int frequency, int given)
{
  if (frequency == slLightingPass::FLAT)
  {
    return VTK_FLAT;
  }
  return given == VTK_FLAT ? VTK_PHONG : given;
}

/// The properties whose interpolation the pass changed.
using InterpolationChanges = WeakKeyedMap<vtkProperty, InterpolationChange>;

/// Gives each property of @p changes still alive the interpolation the pass
/// found, where it still has the one the pass set: a value the user gave
/// since stays.
void restoreInterpolations(const InterpolationChanges& changes)
{
  changes.ForEachLive([](vtkProperty* property, const InterpolationChange& change) {
    if (property->GetInterpolation() == change.set)
    {
      property->SetInterpolation(change.found);
    }
  });
}

/// restoreInterpolations(@p changes) once @p window has drawn its frame.
/// During a frame a mapper stamps its shaders after it has read the
/// property: a change made then (by a pass freed in a mapper, which holds
/// the last passes it drew with until it draws again) would never rebuild
/// them, and the picture would keep the old interpolation.
void restoreAfterFrame(vtkRenderWindow* window, InterpolationChanges changes)
{
  struct Pending
  {
    InterpolationChanges changes;
    vtkCommand* command;
  };
  vtkNew<vtkCallbackCommand> command;
  command->SetClientData(new Pending{ std::move(changes), command.GetPointer() });
  command->SetClientDataDeleteCallback([](void* pending) { delete static_cast<Pending*>(pending); });
  command->SetCallback([](vtkObject* caller, unsigned long, void* data, void*) {
    auto* pending = static_cast<Pending*>(data);
    restoreInterpolations(pending->changes);
    caller->RemoveObserver(pending->command); // VTK keeps the command alive until it returns
  });
  window->AddObserver(vtkCommand::EndEvent, command);
}

/// A renderer the pass has drawn, watched for a change of its pass.
struct DrawnRenderer
{
  /// The renderer's pass when the pass last drew it (the pass itself, or a
  /// pass around it), by address: only a change of it counts.
  const vtkRenderPass* top = nullptr;
  unsigned long observer = 0; ///< the tag of the pass's ModifiedEvent observer
  bool givenBack = false;     ///< the interpolations were given back on a change of its pass
  /// Whether a change of the renderer's pass is taken for the pass's
  /// removal. Off once the pass draws the renderer again, after one, under
  /// another pass: a program that changes the passes around this one every
  /// frame must not have the interpolations given back and set again (and
  /// VTK's shaders rebuilt) every frame.
  bool changeRemoves = true;
};
} // namespace

struct slLightingPass::Internals
{
  std::vector<shadelab::glsl::slLight> LightsVC; // view coordinates
  std::vector<LightUniformNames> Names;
  const MaterialUniformNames FrontMaterialNames{ "slMat" };
  const MaterialUniformNames BackMaterialNames{ "slMatBack" };
  bool Parallel = false;
  bool ReportedTooManyLights = false; // until the lights fit again
  bool WarnedNoNormals = false;
  bool WarnedNoTangents = false;
  bool WarnedShadows = false;
  // Mappers given the slTangentMC attribute (a new mapper at a freed one's
  // address is not taken for it).
  WeakKeyedMap<vtkMapper, bool> TangentMappers;
  // What each shader program the pass sets is (ProgramFacts).
  WeakKeyedMap<vtkShaderProgram, ProgramFacts> Programs;
  // The properties whose interpolation the pass changed, with the user's
  // (weak: the pass keeps no property alive).
  InterpolationChanges Interpolations;
  // The renderers the pass has drawn (WatchRenderer).
  WeakKeyedMap<vtkRenderer, DrawnRenderer> Renderers;

  const ProgramFacts& FactsOf(vtkShaderProgram* program)
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

  // The .brdf file, if any: its GLSL as the shaders hold it, its parameter
  // values (uniforms), and what compiling its GLSL on its own gave.
  std::unique_ptr<shadelab::BrdfFile> Brdf;
  std::string BrdfSource;
  std::vector<glm::vec3> BrdfValues;
  // What compiling each (file, text) gave: "" or its one-line error. VTK
  // keeps built variants, so a text already checked is not seen again.
  std::map<std::string, std::string> BrdfChecked;

  std::string BrdfKey() const { return this->Brdf->path + '\n' + this->BrdfSource; }
  std::string BrdfError;
  int ShaderBuilds = 0;

  std::vector<int> LightTypes() const
  {
    std::vector<int> types;
    for (const shadelab::glsl::slLight& l : this->LightsVC)
    {
      types.push_back(l.type);
    }
    return types;
  }
};

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
    restoreAfterFrame(drawing, std::move(this->Internal->Interpolations));
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

void slLightingPass::SetBrdfFromScene()
{
  const shadelab::SceneBrdf& brdf = this->Scene->GetScene().brdf;
  if (brdf.file.empty())
  {
    this->RemoveBrdf();
    return;
  }
  // Read each time: the file may have been edited since.
  try
  {
    const shadelab::BrdfFile file = shadelab::readBrdfFile(this->Scene->GetBrdfFilePath());
    this->SetBrdf(file, shadelab::brdfParameterValues(file, brdf.parameters));
  }
  catch (const shadelab::Error& e)
  {
    const std::string& source = this->Scene->GetScene().sourceFile;
    this->RemoveBrdf();
    this->Internal->BrdfError = e.what() + (source.empty() ? std::string() : " (brdf of " + source + ")");
    vtkErrorMacro(<< this->Internal->BrdfError);
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
    return false;
  }
  this->SetFrequency(static_cast<int>(frequency));
  return true;
}

void slLightingPass::SetBrdf(const shadelab::BrdfFile& file, const std::vector<glm::vec3>& values)
{
  Internals& in = *this->Internal;
  const std::string source = shaders::brdfSource(shadelab::brdfUniformDeclarations(file), file.shader);
  if (source != in.BrdfSource)
  {
    this->ShaderStageTime.Modified(); // the BRDF's text is compiled into the shaders
  }
  in.Brdf.reset(new shadelab::BrdfFile(file));
  in.BrdfSource = source;
  in.BrdfValues = values;
  in.BrdfValues.resize(file.parameters.size());
  const auto checked = in.BrdfChecked.find(in.BrdfKey());
  in.BrdfError = checked == in.BrdfChecked.end() ? std::string() : checked->second;
  this->Modified();
}

bool slLightingPass::LoadBrdfFile(const char* path)
{
  try
  {
    const shadelab::BrdfFile file = shadelab::readBrdfFile(path ? path : "");
    this->SetBrdf(file, shadelab::brdfParameterValues(file, {}));
    return true;
  }
  catch (const shadelab::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return false;
  }
}

bool slLightingPass::SetBrdfText(const char* text, const char* path)
{
  try
  {
    const shadelab::BrdfFile file = shadelab::parseBrdfText(text ? text : "", path ? path : "(text)");
    this->SetBrdf(file, shadelab::brdfParameterValues(file, {}));
    return true;
  }
  catch (const shadelab::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return false;
  }
}

void slLightingPass::RemoveBrdf()
{
  Internals& in = *this->Internal;
  if (in.Brdf)
  {
    in.Brdf.reset();
    in.BrdfSource.clear();
    in.BrdfValues.clear();
    in.BrdfError.clear();
    this->ShaderStageTime.Modified();
    this->Modified();
  }
}

bool slLightingPass::HasBrdf() const
{
  return this->Internal->Brdf != nullptr;
}

const char* slLightingPass::GetBrdfFileName() const
{
  return this->Internal->Brdf ? this->Internal->Brdf->path.c_str() : "";
}

int slLightingPass::GetNumberOfBrdfParameters() const
{
  return this->Internal->Brdf ? static_cast<int>(this->Internal->Brdf->parameters.size()) : 0;
}

namespace
{
/// Parameter @p i of @p file, or null (after a warning) when out of range.
const shadelab::BrdfParameter* parameterAt(const shadelab::BrdfFile* file, int i)
{
  if (!file || i < 0 || i >= static_cast<int>(file->parameters.size()))
  {
    return nullptr;
  }
  return &file->parameters[static_cast<size_t>(i)];
}

void copyTo(const glm::vec3& v, double out[3])
{
  for (int c = 0; c < 3; ++c)
  {
    out[c] = static_cast<double>(v[c]);
  }
}
} // namespace

const char* slLightingPass::GetBrdfParameterName(int i) const
{
  const shadelab::BrdfParameter* p = parameterAt(this->Internal->Brdf.get(), i);
  return p ? p->name.c_str() : nullptr;
}

int slLightingPass::GetBrdfParameterKind(int i) const
{
  const shadelab::BrdfParameter* p = parameterAt(this->Internal->Brdf.get(), i);
  return p ? static_cast<int>(p->kind) : -1;
}

double slLightingPass::GetBrdfParameterMinimum(int i) const
{
  const shadelab::BrdfParameter* p = parameterAt(this->Internal->Brdf.get(), i);
  return p ? static_cast<double>(p->minimum) : 0.0;
}

double slLightingPass::GetBrdfParameterMaximum(int i) const
{
  const shadelab::BrdfParameter* p = parameterAt(this->Internal->Brdf.get(), i);
  return p ? static_cast<double>(p->maximum) : 0.0;
}

void slLightingPass::GetBrdfParameterDefault(int i, double value[3]) const
{
  const shadelab::BrdfParameter* p = parameterAt(this->Internal->Brdf.get(), i);
  copyTo(p ? p->defaultValue : glm::vec3(0.0f), value);
}

void slLightingPass::GetBrdfParameterValue(int i, double value[3]) const
{
  const shadelab::BrdfParameter* p = parameterAt(this->Internal->Brdf.get(), i);
  copyTo(p ? this->Internal->BrdfValues[static_cast<size_t>(i)] : glm::vec3(0.0f), value);
}

bool slLightingPass::SetBrdfValues(const std::vector<std::string>& assignments)
{
  Internals& in = *this->Internal;
  if (!in.Brdf)
  {
    vtkErrorMacro(<< "no .brdf file to set parameters of");
    return false;
  }
  try
  {
    // The current values first (as assignments), then the new ones: the
    // core parses and checks every value, as it does for --param.
    std::vector<std::string> all;
    for (size_t i = 0; i < in.Brdf->parameters.size(); ++i)
    {
      all.push_back(shadelab::brdfAssignment(in.Brdf->parameters[i], in.BrdfValues[i]));
    }
    all.insert(all.end(), assignments.begin(), assignments.end());
    in.BrdfValues = shadelab::brdfParameterValues(*in.Brdf, all);
  }
  catch (const shadelab::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return false;
  }
  this->Modified(); // a uniform: the shaders stay as they are
  return true;
}

bool slLightingPass::SetBrdfParameter(const char* assignment)
{
  return this->SetBrdfValues({ assignment ? assignment : "" });
}

bool slLightingPass::SetBrdfParameter(const char* name, double value)
{
  return this->SetBrdfValues({ std::string(name ? name : "") + "=" + shadelab::brdfNumberText(value) });
}

bool slLightingPass::SetBrdfParameter(const char* name, double r, double g, double b)
{
  return this->SetBrdfValues(
    { std::string(name ? name : "") + "=" + shadelab::brdfNumberText(r) + "," + shadelab::brdfNumberText(g) + "," + shadelab::brdfNumberText(b) });
}

const char* slLightingPass::GetBrdfError() const
{
  return this->Internal->BrdfError.c_str();
}

int slLightingPass::GetNumberOfShaderBuilds() const
{
  return this->Internal->ShaderBuilds;
}

bool slLightingPass::CheckBrdf(const std::string& checkShader)
{
  Internals& in = *this->Internal;
  const auto checked = in.BrdfChecked.find(in.BrdfKey());
  if (checked != in.BrdfChecked.end())
  {
    in.BrdfError = checked->second;
    return in.BrdfError.empty();
  }
  vtkNew<vtkShader> shader;
  shader->SetType(vtkShader::Fragment);
  shader->SetSource(checkShader);
  const bool compiled = shader->Compile();
  const std::string log = shader->GetError();
  shader->Cleanup();
  in.BrdfError = compiled ? std::string()
                          : shadelab::brdfCompileError(*in.Brdf, log,
                              shaders::brdfShaderFirstLine(checkShader, static_cast<int>(in.Brdf->parameters.size())));
  in.BrdfChecked[in.BrdfKey()] = in.BrdfError;
  if (!compiled)
  {
    vtkErrorMacro(<< in.BrdfError);
  }
  return compiled;
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

void slLightingPass::MatchInterpolation(const vtkRenderState* s)
{
  // VTK's mapper supplies per-face normals under flat interpolation and
  // interpolated point normals otherwise: make it supply what we need
  // (interpolationFor), and remember the user's value to give it back.
  InterpolationChanges& changes = this->Internal->Interpolations;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkActor* actor = vtkActor::SafeDownCast(s->GetPropArray()[i]);
    if (!isLitOpaqueActor(actor))
    {
      continue; // drawn by VTK as without the pass, in its own interpolation
    }
    vtkProperty* property = actor->GetProperty();
    const int current = property->GetInterpolation();
    const InterpolationChange* change = changes.Find(property);
    // A value other than the one the pass set is the user's, and the one
    // to give back from now on.
    const bool userChanged = change && change->set != current;
    const int given = change && !userChanged ? change->found : current;
    const int wanted = interpolationFor(this->Frequency, given);
    // Only on a change: a property's modification time rebuilds the
    // actor's shaders, so the pass never sets it frame after frame.
    if (wanted != current || userChanged)
    {
      property->SetInterpolation(wanted);
      changes.Insert(property, { given, wanted });
    }
  }
}

void slLightingPass::RestoreInterpolations()
{
  restoreInterpolations(this->Internal->Interpolations);
  this->Internal->Interpolations.Clear();
}

void slLightingPass::WatchRenderer(vtkRenderer* renderer)
{
  WeakKeyedMap<vtkRenderer, DrawnRenderer>& renderers = this->Internal->Renderers;
  const DrawnRenderer* known = renderers.Find(renderer);
  if (known && known->top == renderer->GetPass() && !known->givenBack)
  {
    return; // every frame but the first in a renderer
  }
  DrawnRenderer drawn = known ? *known : DrawnRenderer();
  if (!known)
  {
    // vtkRenderer::SetPass() tells no pass, but modifies the renderer.
    drawn.observer = renderer->AddObserver(vtkCommand::ModifiedEvent, this, &slLightingPass::RendererModified);
  }
  // Drawn again after a change of the renderer's pass gave the
  // interpolations back: under the pass it had before, the pass was taken
  // out and put back; under another, that change was one around the pass,
  // not its removal, and such changes are not taken for one again.
  drawn.changeRemoves = drawn.changeRemoves && (!drawn.givenBack || renderer->GetPass() == drawn.top);
  drawn.givenBack = false;
  drawn.top = renderer->GetPass();
  renderers.Insert(renderer, drawn);
}

void slLightingPass::RendererModified(vtkObject* caller, unsigned long, void*)
{
  auto* renderer = static_cast<vtkRenderer*>(caller);
  const DrawnRenderer* drawn = this->Internal->Renderers.Find(renderer);
  if (!drawn || drawn->givenBack || !drawn->changeRemoves || renderer->GetPass() == drawn->top)
  {
    return; // modified for anything but a new pass
  }
  // The renderer's pass changed (vtkRenderer::SetPass): the pass is no
  // longer drawn there, alone or inside the old one. Given back now, before
  // VTK draws a frame without the pass.
  DrawnRenderer givenBack = *drawn;
  givenBack.givenBack = true;
  this->Internal->Renderers.Insert(renderer, givenBack);
  this->RestoreInterpolations();
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
    for (size_t i = 0; i < in.Brdf->parameters.size(); ++i)
    {
      const shadelab::BrdfParameter& p = in.Brdf->parameters[i];
      const glm::vec3& v = in.BrdfValues[i];
      switch (p.kind)
      {
        case shadelab::BrdfParameter::Kind::Float:
          program->SetUniformf(p.name.c_str(), v.x);
          break;
        case shadelab::BrdfParameter::Kind::Bool:
          program->SetUniformi(p.name.c_str(), v.x != 0.0f ? 1 : 0);
          break;
        case shadelab::BrdfParameter::Kind::Color:
          program->SetUniform3f(p.name.c_str(), &v[0]);
          break;
      }
    }
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
