#include "slLitFilter.h"
#include "shadelab/slAtomicMinimum.h"
#include "slConnectivityCheck.h"
#include "slCoreBoundary.h"

#include "slFloat3View.h"
#include "slGlobalBounds.h"
#include "slLightingSetup.h"
#include "slModelCheck.h"
#include "slTangentsCheck.h"
#include "shadelab/LightingGLSL.h"
#include "shadelab/DefaultScene.h"
#include "shadelab/Scene.h"
#include "slScene.h"
#include "slUpdateOrThrow.h"

#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkSMPTools.h>

#include <algorithm>
#include <atomic>
#include <limits>
#include <utility>


vtkCxxSetObjectMacro(slLitFilter, Scene, slScene);
vtkCxxSetObjectMacro(slLitFilter, Lights, vtkLightCollection);
vtkCxxSetObjectMacro(slLitFilter, Property, vtkProperty);
vtkCxxSetObjectMacro(slLitFilter, Camera, vtkCamera);

namespace
{
void toDouble3(const glm::vec3& from, double to[3])
{
  for (int i = 0; i < 3; ++i)
  {
    to[i] = static_cast<double>(from[i]);
  }
}

glm::vec3 toVec3(const double from[3])
{
  return glm::vec3(static_cast<float>(from[0]), static_cast<float>(from[1]), static_cast<float>(from[2]));
}
} // namespace

slLitFilter::slLitFilter()
{
  const shadelab::SceneMaterial& m = shadelab::defaultScene().material;
  toDouble3(m.ambient, this->AmbientColor);
  toDouble3(m.diffuse, this->DiffuseColor);
  toDouble3(m.specular, this->SpecularColor);
  toDouble3(m.emission, this->EmissionColor);
  this->Shininess = static_cast<double>(m.shininess);
}

slLitFilter::~slLitFilter()
{
  this->SetSceneFileName(nullptr);
  this->SetScene(nullptr);
  this->SetLights(nullptr);
  this->SetProperty(nullptr);
  this->SetCamera(nullptr);
}

namespace
{
/// "" or why the lighting cannot use @p data's point normals.
std::string pointNormalsProblem(vtkPointData* data)
{
  // vtkPointData::SetNormals() takes 3-component arrays only.
  vtkDataArray* normals = data->GetNormals();
  if (!normals && data->GetArray("Normals"))
  {
    // A "Normals" array that is not the normals attribute (vtkPointData::SetNormals).
    return "its point array \"Normals\" is not set as its point normals (vtkPointData::SetNormals)";
  }
  if (!normals)
  {
    return "it has no point normals; compute them first (slPolyDataNormals)";
  }
  return std::string();
}
} // namespace

vtkMTimeType slLitFilter::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  for (vtkObject* o : { static_cast<vtkObject*>(this->Scene), static_cast<vtkObject*>(this->Lights),
         static_cast<vtkObject*>(this->Property), static_cast<vtkObject*>(this->Camera) })
  {
    if (o && o->GetMTime() > t)
    {
      t = o->GetMTime();
    }
  }
  // A collection's time changes when lights are added or removed, not when
  // one of them is moved or dimmed: each light counts too.
  if (this->Lights)
  {
    vtkCollectionSimpleIterator it;
    this->Lights->InitTraversal(it);
    while (vtkLight* light = this->Lights->GetNextLight(it))
    {
      t = std::max(t, light->GetMTime());
    }
  }
  return t;
}

vtkTypeBool slLitFilter::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return slProcessRequestSafely(this, outputVector, "input mesh: ",
    [&] { return this->Superclass::ProcessRequest(request, inputVector, outputVector); });
}

int slLitFilter::Fail(vtkPolyData* output, const std::string& message)
{
  if (output)
  {
    output->Initialize();
  }
  vtkErrorMacro(<< message);
  return 0;
}

int slLitFilter::FailOnZeroNormal(vtkPolyData* output, vtkIdType point, vtkIdType points)
{
  return this->Fail(output, "input mesh: point " + std::to_string(point) + " of " + std::to_string(points) +
      " has a zero-length or non-finite normal (ZeroNormalsAreErrors is on)");
}

bool slLitFilter::PrepareLighting(
  vtkPolyData* input, vtkPolyData* output, bool needLight, shadelab::LightingSetup& setup, bool checkNormals)
{
  // First, on every rank: the bounds are a collective operation under MPI,
  // which a rank that fails below must not leave others waiting for.
  double* bounds = this->WholeBounds;
  shadelab::globalBounds(input, bounds);
  vtkSmartPointer<slScene> scene = this->Scene;
  if (this->SceneFileName && *this->SceneFileName)
  {
    scene = vtkSmartPointer<slScene>::New();
    if (!slRunCore(this, output, [&] {
          slCallOrThrow(scene, [&] { return scene->ReadFile(this->SceneFileName); });
        }))
    {
      return false;
    }
  }
  if (this->Model >= 0 || this->OverrideMaterial)
  {
    shadelab::Scene values = scene ? scene->GetScene() : shadelab::defaultScene();
    if (this->Model >= 0)
    {
      values.model = static_cast<shadelab::ShadingModel>(this->Model);
    }
    if (this->OverrideMaterial)
    {
      values.material.ambient = toVec3(this->AmbientColor);
      values.material.diffuse = toVec3(this->DiffuseColor);
      values.material.specular = toVec3(this->SpecularColor);
      values.material.emission = toVec3(this->EmissionColor);
      values.material.shininess = static_cast<float>(this->Shininess);
      slMaterialNumbersInto(this, values.material);
    }
    scene = vtkSmartPointer<slScene>::New();
    scene->SetScene(values);
  }
  if (!input || input->GetNumberOfPoints() == 0)
  {
    this->Fail(output, "input mesh: it is empty (no points)");
    return false;
  }
  const std::string cellProblem = slConnectivityProblem(input);
  if (!cellProblem.empty())
  {
    this->Fail(output, "input mesh: " + cellProblem);
    return false;
  }
  vtkDataArray* normals = input->GetPointData()->GetNormals();
  const std::string normalsProblem = pointNormalsProblem(input->GetPointData());
  if (!normalsProblem.empty())
  {
    this->Fail(output, "input mesh: " + normalsProblem);
    return false;
  }
  if (this->ZeroNormalsAreErrors && checkNormals)
  {
    // The first point whose normal has no direction, found in parallel.
    const shadelab::Float3View view(normals);
    const vtkIdType n = normals->GetNumberOfTuples();
    std::atomic<vtkIdType> firstBad(n);
    vtkSMPTools::For(0, n, [&](vtkIdType begin, vtkIdType end) {
      // Blocks without a bad normal (almost always all of them) are checked
      // without a branch or a square root per point, so the compiler
      // vectorises the test; only a block that has one is searched point by
      // point, with slSafeNormalize itself (what the lighting will use). On
      // squared lengths, conservatively: a direction needs a length above
      // SL_TINY_LENGTH = 1e-18, so dot > 1e-36 (a block with a dot <= 1e-35
      // gets the exact test), and a finite dot.
      const float* xyz = view.data();
      constexpr vtkIdType kBlock = 1024;
      for (vtkIdType first = begin; first < end && first < firstBad.load(); first += kBlock)
      {
        const vtkIdType last = std::min(end, first + kBlock);
        bool blockBad = false;
        for (vtkIdType i = first; i < last; ++i)
        {
          const float* p = xyz + 3 * i;
          const float squared = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
          blockBad |= !(squared > 1e-35f && squared <= std::numeric_limits<float>::max());
        }
        for (vtkIdType i = first; blockBad && i < last; ++i)
        {
          const glm::vec3 unit = shadelab::glsl::slSafeNormalize(view[i]);
          if (glm::dot(unit, unit) < 0.5f) // the zero vector: no direction
          {
            slAtomicMinimum(firstBad, i);
            return;
          }
        }
      }
    });
    if (firstBad.load() < n)
    {
      this->FailOnZeroNormal(output, firstBad.load(), n);
      return false;
    }
  }
  setup = shadelab::makeLightingSetup(scene, this->Lights, this->Property, this->Camera, bounds);
  const bool fromFile = scene && !this->Lights && !scene->GetScene().sourceFile.empty();
  if (!setup.problem.empty())
  {
    const bool fromVTK = this->Lights || this->Property || this->Camera;
    this->Fail(output,
      (fromVTK ? std::string("scene (with the VTK lights, property or camera)")
               : fromFile ? scene->GetScene().sourceFile : std::string("scene")) +
        ": " + setup.problem);
    return false;
  }
  if (needLight && setup.lights.empty())
  {
    this->Fail(output, (fromFile ? scene->GetScene().sourceFile + ": lights" : std::string("scene")) +
        ": it has no lights");
    return false;
  }
  return true;
}

bool slLitFilter::GetTangents(
  vtkPolyData* input, vtkPolyData* output, const shadelab::LightingSetup& setup, vtkDataArray*& tangents)
{
  tangents = nullptr;
  const std::string problem = slTangentsProblem(input, setup.model);
  if (!problem.empty())
  {
    this->Fail(output, "input mesh: " + problem);
    return false;
  }
  if (shadelab::modelNeedsTangents(static_cast<shadelab::ShadingModel>(setup.model)))
  {
    tangents = input->GetPointData()->GetArray("Tangents");
  }
  return true;
}

bool slLitFilter::HasTangents(vtkPolyData* mesh)
{
  vtkDataArray* array = mesh ? mesh->GetPointData()->GetArray("Tangents") : nullptr;
  return array && array->GetNumberOfComponents() == 4 && array->GetNumberOfTuples() == mesh->GetNumberOfPoints();
}

void slLitFilter::SetModel(int model)
{
  if (slCheckModel(this, model, true) && model != this->Model)
  {
    this->Model = model;
    this->Modified();
  }
}

bool slLitFilter::SetModelName(const char* name)
{
  return slSetModelByName(this, name);
}

std::string slLitFilter::GetModelName() const
{
  return slModelNameOf(this->Model);
}

void slLitFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scene: " << this->Scene << "\n";
  os << indent << "Lights: " << this->Lights << "\n";
  os << indent << "Property: " << this->Property << "\n";
  os << indent << "Camera: " << this->Camera << "\n";
  os << indent << "ZeroNormalsAreErrors: " << this->ZeroNormalsAreErrors << "\n";
  os << indent << "SceneFileName: " << (this->SceneFileName ? this->SceneFileName : "(none)") << "\n";
  os << indent << "Model: " << this->Model << (this->Model < 0 ? " (the scene's)" : " (" + this->GetModelName() + ")")
     << "\n";
  os << indent << "OverrideMaterial: " << this->OverrideMaterial << "\n";
  const std::pair<const char*, const double*> colours[] = { { "AmbientColor", this->AmbientColor },
    { "DiffuseColor", this->DiffuseColor }, { "SpecularColor", this->SpecularColor },
    { "EmissionColor", this->EmissionColor } };
  for (const auto& c : colours)
  {
    os << indent << c.first << ": " << c.second[0] << " " << c.second[1] << " " << c.second[2] << "\n";
  }
  os << indent << "Shininess: " << this->Shininess << "\n";
  slPrintMaterialNumberMembers(this, os, indent);
}
