#include "slScene.h"

#include "slCoreBoundary.h"

#include "shadelab/Scene.h"
#include "shadelab/SceneFile.h"

#include <vtkObjectFactory.h>

#include <sstream>

vtkStandardNewMacro(slScene);

slScene::slScene()
  : Data(new shadelab::Scene)
{
}

slScene::~slScene() = default;

const shadelab::Scene& slScene::GetScene() const
{
  return *this->Data;
}

void slScene::SetScene(const shadelab::Scene& scene)
{
  *this->Data = scene;
  this->Modified();
}

bool slScene::ReadFile(const char* path)
{
  return slRunCore(this, [&] { this->SetScene(shadelab::readSceneFile(path ? path : "")); });
}

bool slScene::ReadString(const char* jsonText, const char* nameForMessages)
{
  return slRunCore(this, [&] {
    this->SetScene(
      shadelab::parseScene(jsonText ? jsonText : "", nameForMessages ? nameForMessages : "(string)"));
  });
}

bool slScene::WriteFile(const char* path)
{
  return slRunCore(this, [&] { shadelab::writeSceneFile(*this->Data, path ? path : ""); });
}

std::string slScene::ToJSON() const
{
  return shadelab::sceneToJson(*this->Data);
}

std::string slScene::GetModelName() const
{
  return shadelab::modelName(this->Data->model);
}

bool slScene::SetModelName(const char* name)
{
  if (!name || !shadelab::parseModelName(name, this->Data->model))
  {
    vtkErrorMacro(<< "SetModelName: " << shadelab::modelNameProblem(name));
    return false;
  }
  this->Modified();
  return true;
}

std::string slScene::GetFrequencyName() const
{
  return shadelab::frequencyName(this->Data->frequency);
}

bool slScene::SetFrequencyName(const char* name)
{
  if (!name || !shadelab::parseFrequencyName(name, this->Data->frequency))
  {
    vtkErrorMacro(<< "SetFrequencyName: " << shadelab::frequencyNameProblem(name));
    return false;
  }
  this->Modified();
  return true;
}

int slScene::GetNumberOfLights() const
{
  return static_cast<int>(this->Data->lights.size());
}

int slScene::GetImageWidth() const
{
  return this->Data->width;
}

int slScene::GetImageHeight() const
{
  return this->Data->height;
}

namespace
{
/// @p path resolved against the folder of the scene file @p source.
std::string besideSceneFile(const std::string& path, const std::string& source)
{
  if (path.empty() || path.front() == '/')
  {
    return path;
  }
  const size_t slash = source.find_last_of('/');
  return slash == std::string::npos ? path : source.substr(0, slash + 1) + path;
}
} // namespace

std::string slScene::GetDiffuseTexturePath() const
{
  return besideSceneFile(this->Data->material.diffuseTexture, this->Data->sourceFile);
}

std::string slScene::GetBrdfFilePath() const
{
  return besideSceneFile(this->Data->brdf.file, this->Data->sourceFile);
}

const char* slScene::GetConversionNotes()
{
  this->ConversionNotes = this->LightNotes + this->MaterialNotes;
  return this->ConversionNotes.c_str();
}

void slScene::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Source: " << (this->Data->sourceFile.empty() ? "(built in code)" : this->Data->sourceFile)
     << "\n";
  os << indent << "Model: " << this->GetModelName() << "\n";
  os << indent << "Frequency: " << this->GetFrequencyName() << "\n";
  os << indent << "Lights: " << this->GetNumberOfLights() << "\n";
  os << indent << "ImageSize: " << this->Data->width << " x " << this->Data->height << "\n";
  // Everything else the scene holds (material, camera, each light, the
  // texture and .brdf paths) in the scene file's own words.
  os << indent << "Scene:\n";
  std::istringstream json(this->ToJSON());
  for (std::string line; std::getline(json, line);)
  {
    os << indent.GetNextIndent() << line << "\n";
  }
  os << indent << "ConversionNotes:" << (this->LightNotes.empty() && this->MaterialNotes.empty() ? " (none)" : "")
     << "\n";
  std::istringstream notes(this->LightNotes + this->MaterialNotes);
  for (std::string line; std::getline(notes, line);)
  {
    os << indent.GetNextIndent() << line << "\n";
  }
}
