// shadelab cosine MESH [--scene S.json] [--light I] -o OUT.vtp
#include "CommandLine.h"
#include "Commands.h"
#include "Inputs.h"
#include "MeshJobs.h"
#include "LightingOptions.h"

#include "slCosineField.h"
#include "slScene.h"

#include <vtkNew.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <iostream>

namespace shadelab
{
namespace app
{

namespace
{
int runCosine(const std::vector<std::string>& args)
{
  std::vector<OptionSpec> specs = litOptions();
  // N.L reads neither the lighting model nor the material: no --model.
  specs.erase(std::find_if(specs.begin(), specs.end(), [](const OptionSpec& s) { return s.name == "model"; }));
  specs.push_back({ "light", "l", "INDEX", "only this light (0-based); default: every light, arrays CosTheta_<i>" });
  specs.push_back({ "no-cells", "", "", "point arrays only" });
  specs = withMeshJobOptions(specs);
  const CommandLine cl(args, specs);
  if (cl.has("help"))
  {
    std::cout << "usage: shadelab cosine MESH... [--scene S.json] [--light I] -o OUT\n\n"
                 "Writes the cosine N.L of each light per point and per cell: CosTheta (clamped,\n"
                 "the cosine law) and CosThetaRaw (negative where the surface faces away).\n"
                 "MESH: " << meshFormatsText() << "; point normals are computed if missing.\n"
              << meshJobsHelp() << "\noptions:\n" << CommandLine::describe(specs);
    return 0;
  }
  const std::vector<MeshJob> jobs = meshJobs(cl);
  checkFieldImageOptions(cl, jobs);
  vtkNew<slCosineField> filter;
  vtkSmartPointer<slScene> scene = configureLitFilter(cl, filter);
  filter->SetLightIndex(lightOption(cl, scene));
  filter->SetComputeCellArrays(!cl.has("no-cells"));
  return runMeshJobs("cosine", jobs, [&](const MeshJob& job) {
    filter->SetInputData(loadMeshWithNormals(job.input));
    runLitFilter(filter, job.input);
    writeFieldImageIfAsked(cl, filter->GetOutput(), scene,
      cl.has("light") ? "CosThetaRaw,CosTheta" : "CosThetaRaw_0,CosTheta_0", job.output);
    writeMesh(filter->GetOutput(), job.output, cl);
    std::cout << "wrote " << job.output << "\n";
  });
}

const CommandRegistration registration{ { 30, "cosine", "write the cosine N.L of each light as mesh arrays",
  &runCosine } };
} // namespace

} // namespace app
} // namespace shadelab
