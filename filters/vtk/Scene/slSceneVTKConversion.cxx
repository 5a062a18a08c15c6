// slScene's conversions to and from VTK's vtkLight, vtkProperty and vtkCamera.
#include "slScene.h"

#include "shadelab/CameraPlacement.h"
#include "shadelab/Scene.h"
#include "shadelab/SceneKeys.h"
#include "shadelab/ValueLimits.h"
#include "slCoreBoundary.h"
#include "slImageReader.h"
#include "slUpdateOrThrow.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>

namespace
{
void toDouble(const glm::vec3& v, double out[3])
{
  out[0] = v.x;
  out[1] = v.y;
  out[2] = v.z;
}

glm::vec3 toVec3(const double v[3])
{
  return glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
}

/// Adds @p item, one line, to @p notes.
void note(std::string& notes, const std::string& item)
{
  notes += item + "\n";
}

std::string lightPath(size_t index)
{
  return "lights[" + std::to_string(index) + "]";
}

/// Readies the diffuse texture read into @p image (slImageReader's output,
/// used by nothing else) for a vtkTexture in direct-scalars mode.
///
/// 8-bit images are left as they are (v means v / 255). Deeper ones (16-bit
/// PNG and TIFF, EXR, HDR) come from slImageReader as float, 16-bit values
/// normalised to [0, 1]; vtkTexture's default colour mode would map them
/// through a lookup table over their range (a blue cow). In direct-scalars
/// mode they go up as a float texture (RGB32F: no precision lost, values
/// above 1 kept), so the shaders see the values as stored, as
/// slDiffuseColors takes them on the CPU: HDR values above 1 brighten k_a
/// and k_d, and the pixel is clamped when written. The CPU's rule for the
/// rest keeps the two paths in agreement (and the GPU away from NaN): values
/// that are not finite become 0, the others are clamped to
/// +-kMaxColourValue, in place.
void prepareTextureImage(vtkImageData* image)
{
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (!scalars || vtkUnsignedCharArray::SafeDownCast(scalars))
  {
    return;
  }
  vtkSmartPointer<vtkFloatArray> values = vtkFloatArray::SafeDownCast(scalars);
  if (!values) // slImageReader gives unsigned char or float; any other type becomes float
  {
    values = vtkSmartPointer<vtkFloatArray>::New();
    values->DeepCopy(scalars);
    values->SetName(scalars->GetName());
    image->GetPointData()->SetScalars(values);
  }
  float* v = values->GetPointer(0);
  const float limit = static_cast<float>(shadelab::kMaxColourValue);
  for (vtkIdType i = 0, n = values->GetNumberOfValues(); i < n; ++i)
  {
    v[i] = std::isfinite(v[i]) ? std::max(-limit, std::min(v[i], limit)) : 0.0f;
  }
  values->Modified();
}
} // namespace

void slScene::ApplyLights(vtkRenderer* renderer)
{
  this->LightNotes.clear();
  renderer->RemoveAllLights();
  renderer->AutomaticLightCreationOff();
  const std::vector<shadelab::SceneLight>& lights = this->Data->lights;
  for (size_t i = 0; i < lights.size(); ++i)
  {
    const shadelab::SceneLight& l = lights[i];
    if (!shadelab::lightHasDirection(static_cast<int>(l.type)))
    {
      continue; // folded into the property's ambient colour, see ApplyMaterial()
    }
    vtkNew<vtkLight> light;
    if (l.space == shadelab::LightSpace::Camera)
    {
      light->SetLightTypeToCameraLight();
    }
    else
    {
      light->SetLightTypeToSceneLight();
    }
    double c[3];
    toDouble(l.ambient, c);
    light->SetAmbientColor(c);
    toDouble(l.diffuse, c);
    light->SetDiffuseColor(c);
    toDouble(l.specular, c);
    light->SetSpecularColor(c);
    light->SetIntensity(l.intensity);
    if (l.ambient != glm::vec3(0.0f))
    {
      note(this->LightNotes, lightPath(i) + ".ambient: VTK's shaders ignore a light's ambient colour");
    }

    if (!shadelab::lightTakes(l.type, shadelab::kLightPosition))
    {
      // VTK: light arrives from Position toward FocalPoint.
      light->SetPositional(false);
      light->SetFocalPoint(0.0, 0.0, 0.0);
      toDouble(-l.direction, c);
      light->SetPosition(c);
    }
    else
    {
      light->SetPositional(true);
      toDouble(l.position, c);
      light->SetPosition(c);
      toDouble(l.position + l.direction, c);
      light->SetFocalPoint(c);
      light->SetAttenuationValues(l.attenuation.x, l.attenuation.y, l.attenuation.z);
      if (l.attenuation.x < 1.0f)
      {
        note(this->LightNotes, lightPath(i) +
          ".attenuation: VTK has no min(1, .) clamp, so it brightens where c1 + c2 d + c3 d^2 < 1");
      }
      if (shadelab::lightTakes(l.type, shadelab::kLightCutoff))
      {
        light->SetConeAngle(l.cutoffDegrees);
        light->SetExponent(l.exponent);
        if (l.edgeDegrees > 0.0f)
        {
          note(this->LightNotes, lightPath(i) + ".edge: VTK's spot cone has a hard edge");
        }
      }
      else
      {
        light->SetConeAngle(180.0); // a cone of 90 degrees or more is no spot
      }
    }
    renderer->AddLight(light);
  }
}

void slScene::ApplyMaterial(vtkProperty* property)
{
  this->MaterialNotes.clear();
  const shadelab::SceneMaterial& m = this->Data->material;
  double c[3];
  // VTK adds the property's ambient colour as if under one white ambient
  // light; fold the scene's ambient lights into it: k_a * sum of their colours.
  glm::vec3 ambientLight(0.0f);
  for (const shadelab::SceneLight& l : this->Data->lights)
  {
    if (!shadelab::lightHasDirection(static_cast<int>(l.type)))
    {
      ambientLight += l.intensity * l.ambient;
    }
  }
  property->SetAmbient(1.0);
  toDouble(m.ambient * ambientLight, c);
  property->SetAmbientColor(c);
  property->SetDiffuse(1.0);
  toDouble(m.diffuse, c);
  property->SetDiffuseColor(c);
  const bool lambert = this->Data->model == shadelab::ShadingModel::Lambert ||
    this->Data->model == shadelab::ShadingModel::LambertNormalized;
  property->SetSpecular(lambert ? 0.0 : 1.0);
  toDouble(m.specular, c);
  property->SetSpecularColor(c);
  property->SetSpecularPower(m.shininess);
  if (m.emission != glm::vec3(0.0f))
  {
    note(this->MaterialNotes, "material.emission: VTK's built-in lighting has no emission term");
  }
  switch (this->Data->frequency)
  {
    case shadelab::ShadingFrequency::Flat:
      property->SetInterpolationToFlat();
      break;
    case shadelab::ShadingFrequency::Gouraud:
      property->SetInterpolationToGouraud();
      note(this->MaterialNotes, "shading.frequency: VTK 9.1 lights Gouraud per fragment, like Phong");
      break;
    case shadelab::ShadingFrequency::Phong:
      property->SetInterpolationToPhong();
      break;
  }
  const shadelab::ShadingModel model = this->Data->model;
  if (model != shadelab::ShadingModel::Lambert && model != shadelab::ShadingModel::Phong)
  {
    note(this->MaterialNotes, std::string("shading.model: VTK's built-in lighting does not do \"") +
      shadelab::modelName(model) + "\"; it shows " + (lambert ? "lambert" : "phong"));
  }
}

void slScene::ApplyCamera(vtkCamera* camera, const double bounds[6], int width, int height)
{
  const shadelab::CameraView view = shadelab::placeCamera(this->Data->camera, bounds,
    width > 0 ? width : this->Data->width, height > 0 ? height : this->Data->height);
  camera->SetViewAngle(view.viewAngle);
  camera->SetPosition(view.position.x, view.position.y, view.position.z);
  camera->SetFocalPoint(view.focalPoint.x, view.focalPoint.y, view.focalPoint.z);
  camera->SetViewUp(view.viewUp.x, view.viewUp.y, view.viewUp.z);
  camera->SetParallelScale(view.parallelScale);
  camera->SetClippingRange(view.nearPlane, view.farPlane);
}

void slScene::ApplyCamera(vtkRenderer* renderer)
{
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  const int* size = renderer->GetRenderWindow() ? renderer->GetSize() : nullptr;
  const bool sized = size && size[0] > 0 && size[1] > 0;
  this->ApplyCamera(renderer->GetActiveCamera(), bounds, sized ? size[0] : 0, sized ? size[1] : 0);
  renderer->ResetCameraClippingRange();
}

void slScene::ApplyToRenderer(vtkRenderer* renderer)
{
  this->ApplyToRenderer(renderer, nullptr, 0, 0);
}

void slScene::ApplyToRenderer(vtkRenderer* renderer, const double bounds[6], int width, int height)
{
  double c[3];
  toDouble(this->Data->background, c);
  renderer->SetBackground(c);
  this->ApplyLights(renderer);
  if (bounds)
  {
    this->ApplyCamera(renderer->GetActiveCamera(), bounds, width, height);
    renderer->ResetCameraClippingRange();
  }
  else
  {
    this->ApplyCamera(renderer);
  }
}

bool slScene::ReadDiffuseTexture(vtkImageData* image)
{
  image->Initialize();
  const std::string texturePath = this->GetDiffuseTexturePath();
  if (texturePath.empty())
  {
    return true;
  }
  vtkNew<slImageReader> reader;
  reader->SetFileName(texturePath.c_str());
  return slRunCore(this, [&] {
    try
    {
      slUpdateOrThrow(reader);
    }
    catch (const shadelab::Error& e)
    {
      // The reader names the image; the scene names the key that asked for it.
      throw shadelab::Error(std::string(e.what()) + " (material.diffuseTexture of " +
        (this->Data->sourceFile.empty() ? std::string("the scene") : this->Data->sourceFile) + ")");
    }
    image->ShallowCopy(reader->GetOutput());
  });
}

bool slScene::ApplyToActor(vtkActor* actor)
{
  this->ApplyMaterial(actor->GetProperty());
  if (this->GetDiffuseTexturePath().empty())
  {
    actor->SetTexture(nullptr);
    return true;
  }
  vtkNew<vtkImageData> image;
  if (!this->ReadDiffuseTexture(image))
  {
    return false;
  }
  prepareTextureImage(image);
  vtkNew<vtkTexture> texture;
  // The image, not the reader: it is read once and not again at a render.
  texture->SetInputData(image);
  // Unsigned char as v / 255, float as it is (see prepareTextureImage);
  // never through a lookup table.
  texture->SetColorModeToDirectScalars();
  texture->InterpolateOn();
  texture->MipmapOn();
  // VTK multiplies the texture into the ambient and diffuse colours: the
  // scene's k_a and k_d act as tints of the texture.
  actor->SetTexture(texture);
  return true;
}

void slScene::SetLightsFromVTK(vtkLightCollection* lights)
{
  this->LightNotes.clear();
  std::vector<shadelab::SceneLight>& out = this->Data->lights;
  out.clear();
  // VTK lights every actor with its property's ambient colour as if under a
  // white ambient light of intensity 1; make that light explicit.
  shadelab::SceneLight implicitAmbient;
  implicitAmbient.name = "VTK property ambient";
  implicitAmbient.type = shadelab::LightType::Ambient;
  implicitAmbient.ambient = glm::vec3(1.0f);
  implicitAmbient.diffuse = implicitAmbient.specular = glm::vec3(0.0f);
  out.push_back(implicitAmbient);
  lights->InitTraversal();
  size_t index = 0;
  for (vtkLight* light = lights->GetNextItem(); light; light = lights->GetNextItem(), ++index)
  {
    if (!light->GetSwitch())
    {
      note(this->LightNotes, "VTK light " + std::to_string(index) + " is switched off; skipped");
      continue;
    }
    shadelab::SceneLight l;
    l.name = "VTK light " + std::to_string(index); // what messages about it call it
    l.ambient = toVec3(light->GetAmbientColor());
    l.diffuse = toVec3(light->GetDiffuseColor());
    l.specular = toVec3(light->GetSpecularColor());
    l.intensity = static_cast<float>(light->GetIntensity());
    // A scene light's TransformMatrix (set by the user) places it in the
    // world, as VTK lights it; a camera light's is the camera's, which VTK
    // sets each frame, and the light stays in camera space here.
    double p[3], f[3];
    if (light->LightTypeIsSceneLight())
    {
      light->GetTransformedPosition(p);
      light->GetTransformedFocalPoint(f);
    }
    else
    {
      light->GetPosition(p);
      light->GetFocalPoint(f);
    }
    glm::vec3 position = toVec3(p);
    glm::vec3 focal = toVec3(f);
    if (light->LightTypeIsHeadlight())
    {
      // A headlight sits at the camera and shines at the focal point.
      l.space = shadelab::LightSpace::Camera;
      position = glm::vec3(0.0f, 0.0f, 1.0f);
      focal = glm::vec3(0.0f);
    }
    else if (light->LightTypeIsCameraLight())
    {
      l.space = shadelab::LightSpace::Camera;
    }
    l.direction = focal - position;
    if (!shadelab::directionProblem(l.direction).empty())
    {
      l.direction = glm::vec3(0.0f, 0.0f, -1.0f);
      note(this->LightNotes, "VTK light " + std::to_string(index) + ": position equals focal point; pointing along -z");
    }
    if (!light->GetPositional())
    {
      l.type = shadelab::LightType::Directional;
    }
    else
    {
      l.position = position;
      double a[3];
      light->GetAttenuationValues(a);
      l.attenuation = toVec3(a);
      if (light->GetConeAngle() < 90.0)
      {
        l.type = shadelab::LightType::Spot;
        l.cutoffDegrees = static_cast<float>(light->GetConeAngle());
        l.exponent = static_cast<float>(light->GetExponent());
      }
      else
      {
        l.type = shadelab::LightType::Point;
      }
    }
    out.push_back(l);
  }
  this->Modified();
}

void slScene::SetMaterialFromVTK(vtkProperty* property)
{
  this->MaterialNotes.clear(); // reading a vtkProperty notes nothing
  shadelab::SceneMaterial& m = this->Data->material;
  m.ambient = static_cast<float>(property->GetAmbient()) * toVec3(property->GetAmbientColor());
  m.diffuse = static_cast<float>(property->GetDiffuse()) * toVec3(property->GetDiffuseColor());
  m.specular = static_cast<float>(property->GetSpecular()) * toVec3(property->GetSpecularColor());
  m.emission = glm::vec3(0.0f);
  m.shininess = static_cast<float>(property->GetSpecularPower());
  switch (property->GetInterpolation())
  {
    case VTK_FLAT:
      this->Data->frequency = shadelab::ShadingFrequency::Flat;
      break;
    case VTK_GOURAUD:
      this->Data->frequency = shadelab::ShadingFrequency::Gouraud;
      break;
    default:
      this->Data->frequency = shadelab::ShadingFrequency::Phong;
      break;
  }
  this->Modified();
}

void slScene::SetCameraFromVTK(vtkCamera* camera)
{
  shadelab::SceneCamera& c = this->Data->camera;
  c.hasPosition = true;
  c.position = toVec3(camera->GetPosition());
  c.focalPoint = toVec3(camera->GetFocalPoint());
  c.viewUp = toVec3(camera->GetViewUp());
  c.viewAngle = static_cast<float>(camera->GetViewAngle());
  c.azimuth = c.elevation = 0.0f;
  this->Modified();
}
