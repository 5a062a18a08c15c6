// shadelab normals MESH... -o OUT [--weighting W] [--feature-angle DEG] [...]
#include "CommandLine.h"
#include "Counted.h"
#include "Commands.h"
#include "Inputs.h"
#include "MeshJobs.h"
#include "NormalsOptions.h"
#include "OutputFormats.h"

#include "slPolyDataNormals.h"

#include <vtkNew.h>
#include <vtkPolyData.h>

#include <iostream>

namespace shadelab
{
namespace app
{

namespace
{
/// Normals of one mesh, written to @p output. Throws shadelab::Error.
void computeNormals(const CommandLine& cl, const MeshJob& job)
{
  vtkNew<slPolyDataNormals> normals;
  applyNormalsOptions(cl, normals);
  normals->SetComputeCellNormals(cl.has("cells"));
  vtkSmartPointer<vtkPolyData> mesh = loadMesh(job.input);
  noteNonPolygonCells(mesh, "normals", job.input);
  normals->SetInputData(mesh);
  vtkSmartPointer<vtkPolyData> out = runMeshFilter(normals, job.input);
  writeMesh(out, job.output, cl);
  std::cout << "wrote " << job.output << ": " << counted(out->GetNumberOfPoints(), "point") << " ("
            << out->GetNumberOfPoints() - mesh->GetNumberOfPoints() << " added along sharp edges), "
            << counted(out->GetNumberOfPolys(), "polygon") << ", " << normals->GetNumberOfFlippedPolygons()
            << " reversed, weighting " << slPolyDataNormals::GetWeightingName(normals->GetWeighting()) << "\n";
}

int runNormals(const std::vector<std::string>& args)
{
  std::vector<OptionSpec> specs{
    { "output", "o", "FILE", outputHelp("mesh to write", OutputKind::Mesh) },
    { "cells", "", "", "also write face normals (cell array \"Normals\"; VTP and VTK keep it)" },
  };
  for (const OptionSpec& s : normalsOptionSpecs())
  {
    specs.push_back(s);
  }
  specs.push_back({ "help", "h", "", "show this help" });
  specs = withMeshJobOptions(specs);
  const CommandLine cl(args, specs);
  if (cl.has("help"))
  {
    std::cout << "usage: shadelab normals MESH... -o OUT [options]\n\n"
                 "Computes vertex normals (point array \"Normals\") of MESH ("
              << meshFormatsText()
              << ") with slPolyDataNormals: weighted face normals,\n"
                 "points split along sharp edges, polygons oriented consistently.\n"
              << meshJobsHelp() << "\noptions:\n" << CommandLine::describe(specs);
    return 0;
  }
  return runMeshJobs("normals", meshJobs(cl), [&cl](const MeshJob& job) { computeNormals(cl, job); });
}

const CommandRegistration registration{ { 20, "normals",
  "compute vertex and face normals (weighting, sharp edges, orientation)", &runNormals } };
} // namespace

} // namespace app
} // namespace shadelab
