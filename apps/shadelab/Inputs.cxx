#include "Inputs.h"

#include "CommandLine.h"
#include "MaterialOptions.h"

#include "shadelab/AtomicFile.h"
#include "shadelab/DefaultScene.h"
#include "shadelab/Scene.h"
#include "shadelab/SceneLimits.h"
#include "slImageWriter.h"
#include "slMeshReader.h"
#include "slMeshWriter.h"
#include "slScene.h"
#include "slTangentsCheck.h"
#include "slUpdateOrThrow.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <cstdio>
#include <sstream>

namespace shadelab
{
namespace app
{

const char* meshFormatsText()
{
  return "OBJ, PLY, STL, VTP, VTK, OFF or glTF";
}

vtkSmartPointer<vtkPolyData> loadMesh(const std::string& path)
{
  return inStep("reading", [&] {
    vtkNew<slMeshReader> reader;
    reader->SetFileName(path.c_str());
    slUpdateOrThrow(reader);
    vtkSmartPointer<vtkPolyData> mesh = vtkSmartPointer<vtkPolyData>::New();
    mesh->ShallowCopy(reader->GetOutput());
    return mesh;
  });
}

OptionSpec sceneOption()
{
  // shadelab::defaultScene()'s lights, as --light counts them.
  return { "scene", "s", "FILE",
    "JSON scene (default: ShadeLab's built-in scene: key and fill lights in camera space, and an ambient light)" };
}

vtkSmartPointer<slScene> loadScene(const std::string& path)
{
  auto scene = vtkSmartPointer<slScene>::New();
  if (path.empty())
  {
    scene->SetScene(shadelab::defaultScene());
  }
  else
  {
    slCallOrThrow(scene, [&] { return scene->ReadFile(path.c_str()); });
  }
  return scene;
}

namespace
{
std::string commaSeparated(const std::vector<std::string>& names)
{
  std::string out;
  for (const std::string& name : names)
  {
    out += (out.empty() ? "" : ", ") + name;
  }
  return out;
}
} // namespace

std::string modelNameList()
{
  return commaSeparated(modelNames());
}

std::string modelOptionHelp()
{
  return "override the scene's lighting model: " + modelNameList();
}

ShadingModel parseModelOption(const std::string& option, const std::string& value)
{
  ShadingModel model;
  if (!parseModelName(value, model))
  {
    throw UsageError("--" + option + ": " + modelNameProblem(value.c_str()));
  }
  return model;
}

std::vector<ShadingModel> parseModelList(const std::string& option, const std::string& value, bool allowAll)
{
  std::vector<ShadingModel> models;
  if (allowAll && value == "all")
  {
    for (const std::string& name : modelNames())
    {
      models.push_back(parseModelOption(option, name));
    }
    return models;
  }
  std::istringstream names(value);
  for (std::string name; std::getline(names, name, ',');)
  {
    models.push_back(parseModelOption(option, name));
  }
  if (models.empty())
  {
    throw UsageError("--" + option + ": no lighting model named");
  }
  return models;
}

void applySceneOverrides(const CommandLine& cl, slScene* scene)
{
  if (cl.has("model"))
  {
    scene->SetModelName(modelName(parseModelOption("model", cl.get("model"))));
  }
  if (cl.has("frequency") && !scene->SetFrequencyName(cl.get("frequency").c_str()))
  {
    throw UsageError("--frequency: \"" + cl.get("frequency") + "\" is not one of flat, gouraud, phong");
  }
  Scene values = scene->GetScene();
  applyMaterialOptions(cl, values.material);
  scene->SetScene(values);
}

void checkTangentsFor(slScene* scene, vtkPolyData* mesh, const std::string& path)
{
  if (!scene->GetScene().brdf.file.empty())
  {
    return; // the .brdf file's BRDF is drawn, not the model
  }
  checkTangentsFor(scene->GetScene().model, mesh, path);
}

void checkTangentsFor(ShadingModel model, vtkPolyData* mesh, const std::string& path)
{
  const std::string problem = slTangentsProblem(mesh, static_cast<int>(model));
  if (!problem.empty())
  {
    throw Error(path + ": " + problem);
  }
}

void checkLightOption(const CommandLine& cl, int light, slScene* scene)
{
  const int count = scene->GetNumberOfLights();
  if (light >= count)
  {
    throw Error("--light: light " + std::to_string(light) + " is out of range: " +
      (cl.has("scene") ? cl.get("scene") : std::string("the built-in scene")) + " has " + std::to_string(count) +
      (count == 1 ? " light" : " lights"));
  }
}

int lightOption(const CommandLine& cl, slScene* scene)
{
  const int light = cl.has("light") ? cl.getIndex("light", 0, 0, 1000000) : -1;
  checkLightOption(cl, light, scene);
  return light;
}

void parseSize(const std::string& text, int& width, int& height)
{
  // Digits only, read without overflow (sscanf's %d wraps 4294967360 to 64).
  auto side = [](const std::string& digits, int& value) {
    if (digits.empty() || digits.size() > 5 || digits.find_first_not_of("0123456789") != std::string::npos)
    {
      return false;
    }
    value = std::stoi(digits);
    return value >= kMinImageSize && value <= kMaxImageSize;
  };
  const size_t x = text.find_first_of("xX");
  if (x == std::string::npos || !side(text.substr(0, x), width) || !side(text.substr(x + 1), height))
  {
    throw UsageError("--size: \"" + text + "\" is not WxH with " + std::to_string(kMinImageSize) +
      " <= W, H <= " + std::to_string(kMaxImageSize));
  }
}

OptionSpec meshCompressionOption()
{
  std::vector<std::string> names;
  for (int c = slMeshWriter::NONE; c <= slMeshWriter::ZLIB; ++c)
  {
    names.emplace_back(slMeshWriter::GetCompressionName(c));
  }
  return { "compress", "", "NAME",
    "VTP compression: lz4 (default; fast), zlib (smaller, about 6 times slower to write) or none", names };
}

void writeMesh(vtkPolyData* mesh, const std::string& path, const CommandLine& cl)
{
  // The parser has checked the name against meshCompressionOption()'s list.
  const int compression = slMeshWriter::GetCompressionByName(
    cl.get("compress", slMeshWriter::GetCompressionName(slMeshWriter::LZ4)));
  inStep("writing " + path, [&] {
    vtkNew<slMeshWriter> writer;
    writer->SetCompression(compression);
    writer->SetInputData(mesh);
    writer->SetFileName(path.c_str());
    slCallOrThrow(writer, [&] { return writer->Write(); });
  });
}

void writeImage(vtkImageData* image, const std::string& path)
{
  inStep("writing " + path, [&] {
    vtkNew<slImageWriter> writer;
    writer->SetInputData(image);
    writer->SetFileName(path.c_str());
    slCallOrThrow(writer, [&] { return writer->Write(); });
  });
}

void checkOutputsCanBeCreated(const std::vector<std::string>& paths)
{
  for (const std::string& path : paths)
  {
    // Creates the temporary file the write would make, and removes it.
    const AtomicOutput probe(path);
  }
}

} // namespace app
} // namespace shadelab
