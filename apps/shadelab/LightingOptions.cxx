#include "LightingOptions.h"
#include "OutputFormats.h"

#include "Inputs.h"
#include "slFieldImageRenderer.h"
#include "slLitFilter.h"
#include "slPolyDataNormals.h"
#include "slScene.h"
#include "slUpdateOrThrow.h"

#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <iostream>
#include <sstream>

namespace shadelab
{
namespace app
{

std::vector<OptionSpec> litOptions()
{
  return {
    sceneOption(),
    { "model", "", "NAME", modelOptionHelp() },
    { "output", "o", "FILE", outputHelp("mesh to write; .vtp and .vtk keep the arrays", OutputKind::Mesh) },
    meshCompressionOption(),
    { "allow-zero-normals", "", "", "light zero-length normals as 'no direction' instead of failing" },
    { "image", "", "FILE", outputHelp("also write an image of the fields, colour-mapped, with the lights drawn", OutputKind::Image) },
    { "fields", "", "A,B,...", "arrays the image shows (default depends on the subcommand)" },
    { "help", "h", "", "show this help" },
  };
}

vtkSmartPointer<vtkPolyData> loadMeshWithNormals(const std::string& path)
{
  vtkSmartPointer<vtkPolyData> mesh = loadMesh(path);
  if (mesh->GetNumberOfPoints() == 0)
  {
    throw Error(path + ": the mesh is empty (no points)");
  }
  if (mesh->GetPointData()->GetNormals())
  {
    return mesh;
  }
  // ShadeLab's own normals: angle weights, no splitting (the output keeps
  // the input's points, so the arrays line up with it), seams welded.
  vtkNew<slPolyDataNormals> normals;
  normals->SetInputData(mesh);
  normals->SplittingOff();
  normals->ConsistencyOn();
  normals->WeldCoincidentPointsOn();
  inStep("in slPolyDataNormals", [&] { slUpdateOrThrow(normals, path + ": "); });
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  return out;
}

vtkSmartPointer<slScene> configureLitFilter(const CommandLine& cl, slLitFilter* filter)
{
  vtkSmartPointer<slScene> scene = loadScene(cl.get("scene"));
  applySceneOverrides(cl, scene);
  filter->SetScene(scene);
  filter->SetZeroNormalsAreErrors(!cl.has("allow-zero-normals"));
  return scene;
}

void runLitFilter(slLitFilter* filter, const std::string& meshPath)
{
  try
  {
    inStep(std::string("in ") + filter->GetClassName(), [&] { slUpdateOrThrow(filter); });
  }
  catch (const Error& e)
  {
    // The filter knows its input only as "input mesh"; the command knows the file.
    std::string message = e.what();
    const std::string generic = "input mesh";
    const std::string memory = "out of memory"; // VTK's allocation failures (slErrorCapture)
    if (message.compare(0, generic.size(), generic) == 0)
    {
      message = meshPath + message.substr(generic.size());
    }
    else if (message.compare(0, memory.size(), memory) == 0)
    {
      message = meshPath + ": " + message;
    }
    const std::string flag = "(ZeroNormalsAreErrors is on)";
    const size_t at = message.find(flag);
    if (at != std::string::npos)
    {
      message.replace(at, flag.size(), "(--allow-zero-normals lights such points without direction)");
    }
    throw Error(message);
  }
}

} // namespace app
} // namespace shadelab

namespace shadelab
{
namespace app
{

void checkFieldImageOptions(const CommandLine& cl, const std::vector<MeshJob>& jobs)
{
  checkSingleMeshOption(cl, "image", jobs);
  checkOutputOption(cl, "image", { OutputKind::Image });
  if (cl.has("fields") && !cl.has("image"))
  {
    throw UsageError("--fields: only with --image FILE (it chooses the arrays the image shows)");
  }
}

void writeFieldImageIfAsked(const CommandLine& cl, vtkPolyData* mesh, slScene* scene, const std::string& defaultFields,
  const std::string& meshOutput)
{
  if (!cl.has("image"))
  {
    return;
  }
  // The mesh is written after the image: a mesh output that cannot be made
  // must stop the command before the image replaces an existing file.
  checkOutputsCanBeCreated({ cl.get("image"), meshOutput });
  vtkNew<slFieldImageRenderer> image;
  image->SetMesh(mesh);
  image->SetScene(scene);
  std::istringstream names(cl.get("fields", defaultFields));
  for (std::string name; std::getline(names, name, ',');)
  {
    if (!name.empty())
    {
      image->AddField(name.c_str());
    }
  }
  image->SetPanelWidth(480);
  image->SetPanelHeight(360);
  slCallOrThrow(image, [&] { return image->Render(); }, cl.get("image") + ": ");
  writeImage(image->GetImage(), cl.get("image"));
  std::cout << "wrote " << cl.get("image") << "\n";
}

} // namespace app
} // namespace shadelab
