// shadelab light MESH [--scene S.json] -o OUT.vtp
#include "BaseColourOptions.h"
#include "CommandLine.h"
#include "Commands.h"
#include "Inputs.h"
#include "MeshJobs.h"
#include "LightingOptions.h"
#include "MaterialOptions.h"
#include "slScene.h"

#include "slRadianceFilter.h"

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
  for (const OptionSpec& spec : baseColourOptions())
  {
    specs.push_back(spec);
  }
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
  checkBaseColourOptions(cl);
  vtkNew<slRadianceFilter> filter;
  vtkSmartPointer<slScene> scene = configureLitFilter(cl, filter);
  filter->SetPerLightArrays(cl.has("per-light"));
  // As reference takes it, so that the two agree.
  const BaseColour base(cl, scene);
  return runMeshJobs("light", jobs, [&](const MeshJob& job) {
    vtkSmartPointer<vtkPolyData> mesh = loadMeshWithNormals(job.input);
    base.applyTo(filter, mesh);
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
