// shadelab light MESH [--scene S.json] -o OUT.vtp
#include "CommandLine.h"
#include "Commands.h"
#include "Inputs.h"
#include "MeshJobs.h"
#include "LightingOptions.h"
#include "MaterialOptions.h"
#include "slScene.h"
#include "slUpdateOrThrow.h"

#include "slImageReader.h"
#include "slRadianceFilter.h"
#include "slSceneTexture.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <iostream>

namespace shadelab
{
namespace app
{

namespace
{
int runLight(const std::vector<std::string>& args)
{
  std::vector<OptionSpec> specs = withMaterialOptions(litOptions(), "default: the scene's");
  specs.push_back({ "per-light", "", "", "also write Radiance_<i> for every light i" });
  specs.push_back({ "diffuse-array", "", "NAME", "an RGB(A) point array of MESH: a base colour multiplying k_a and k_d (as in render)" });
  specs.push_back({ "diffuse-texture", "", "FILE", "an image: a base colour multiplying k_a and k_d at the texture coordinates (default: the scene's material.diffuseTexture)" });
  specs = withMeshJobOptions(specs);
  const CommandLine cl(args, specs);
  if (cl.has("help"))
  {
    std::cout << "usage: shadelab light MESH... [--scene S.json] -o OUT\n\n"
                 "Evaluates the lighting equation per point and writes the point arrays Ambient,\n"
                 "Diffuse, Specular, Emission and Radiance (RGB, linear).\n"
                 "MESH: " << meshFormatsText() << "; point normals are computed if missing.\n"
              << meshJobsHelp() << "\noptions:\n" << CommandLine::describe(specs);
    return 0;
  }
  const std::vector<MeshJob> jobs = meshJobs(cl);
  checkFieldImageOptions(cl, jobs);
  if (cl.has("diffuse-array") && cl.has("diffuse-texture"))
  {
    // The filter would take the array and never read the texture.
    throw UsageError("--diffuse-texture: give either --diffuse-array or --diffuse-texture, not both");
  }
  vtkNew<slRadianceFilter> filter;
  vtkSmartPointer<slScene> scene = configureLitFilter(cl, filter);
  filter->SetPerLightArrays(cl.has("per-light"));
  if (cl.has("diffuse-array"))
  {
    filter->SetDiffuseColorArrayName(cl.get("diffuse-array").c_str());
  }
  vtkNew<slImageReader> texture;
  // Without --diffuse-texture or --diffuse-array, the scene's
  // material.diffuseTexture, as render draws it (and reference applies it).
  vtkSmartPointer<vtkImageData> sceneTexture;
  if (cl.has("diffuse-texture"))
  {
    texture->SetFileName(cl.get("diffuse-texture").c_str());
    slUpdateOrThrow(texture);
    filter->SetDiffuseTexture(texture->GetOutput());
  }
  else if (!cl.has("diffuse-array"))
  {
    sceneTexture = slReadSceneTexture(scene);
  }
  return runMeshJobs("light", jobs, [&](const MeshJob& job) {
    vtkSmartPointer<vtkPolyData> mesh = loadMeshWithNormals(job.input);
    if (sceneTexture)
    {
      filter->SetDiffuseTexture(slSceneTextureFor(sceneTexture, mesh));
    }
    filter->SetInputData(mesh);
    runLitFilter(filter, job.input);
    writeFieldImageIfAsked(cl, filter->GetOutput(), scene, "Ambient,Diffuse,Specular,Radiance", job.output);
    writeMesh(filter->GetOutput(), job.output, cl);
    std::cout << "wrote " << job.output << "\n";
  });
}

const CommandRegistration registration{ { 31, "light",
  "write the lighting equation's terms (Ambient ... Radiance) as point arrays", &runLight } };
} // namespace

} // namespace app
} // namespace shadelab
