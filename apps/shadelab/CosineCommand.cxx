// shadelab cosine MESH [--scene S.json] [--light I] -o OUT.vtp
#include "CommandLine.h"
#include "Commands.h"
#include "Inputs.h"
#include "MeshJobs.h"
#include "LightingOptions.h"
#include "OutputFormats.h"

#include "slCosineField.h"
#include "slScene.h"

#include <vtkNew.h>
#include <vtkPolyData.h>

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
  checkSingleMeshOption(cl, "image", jobs);
  checkOutputOption(cl, "image", { OutputKind::Image });
  vtkNew<slCosineField> filter;
  vtkSmartPointer<slScene> scene = configureLitFilter(cl, filter);
  filter->SetLightIndex(cl.getIndex("light", -1, -1, 1000000));
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
