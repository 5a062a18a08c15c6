// shadelab normals MESH... -o OUT [--weighting W] [--feature-angle DEG] [...]
#include "CommandLine.h"
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
/// Normals of one mesh, written to @p output. Throws JobError.
void computeNormals(const CommandLine& cl, const MeshJob& job)
{
  vtkNew<slPolyDataNormals> normals;
  applyNormalsOptions(cl, normals);
  normals->SetComputeCellNormals(cl.has("cells"));
  vtkSmartPointer<vtkPolyData> mesh = loadMesh(job.input);
  noteNonPolygonCells(mesh, "normals", job.input);
  normals->SetInputData(mesh);
  vtkSmartPointer<vtkPolyData> out = runMeshFilter(normals, job.input);
  writeMesh(out, job.output);
  std::cout << "wrote " << job.output << ": " << out->GetNumberOfPoints() << " points ("
            << out->GetNumberOfPoints() - mesh->GetNumberOfPoints() << " added along sharp edges), "
            << out->GetNumberOfPolys() << " polygons, " << normals->GetNumberOfFlippedPolygons()
            << " reversed, weighting " << slPolyDataNormals::GetWeightingName(normals->GetWeighting()) << "\n";
}

int runNormals(const std::vector<std::string>& args)
{
  std::vector<OptionSpec> specs{
    { "output", "o", "OUT", outputHelp("mesh to write", OutputKind::Mesh) + ", or an existing folder" },
    meshFormatOption(),
    { "cells", "", "", "also write face normals (cell array \"Normals\"; VTP and VTK keep it)" },
  };
  for (const OptionSpec& s : normalsOptionSpecs())
  {
    specs.push_back(s);
  }
  specs.push_back({ "help", "h", "", "show this help" });
  const CommandLine cl(args, specs);
  if (cl.has("help"))
  {
    std::cout << "usage: shadelab normals MESH... -o OUT [options]\n\n"
                 "Computes vertex normals (point array \"Normals\") of MESH ("
              << meshFormatsText()
              << ") with slPolyDataNormals: weighted face normals,\n"
                 "points split along sharp edges, polygons oriented consistently.\n"
                 "With -o FOLDER, each MESH is written to FOLDER/NAME.EXT; a MESH that fails is\n"
                 "reported and the others are still done (exit status 1 if any failed).\n\noptions:\n"
              << CommandLine::describe(specs);
    return 0;
  }
  const std::vector<MeshJob> jobs = meshJobs(cl);
  if (jobs.size() == 1)
  {
    computeNormals(cl, jobs[0]);
    return 0;
  }
  int failed = 0;
  for (const MeshJob& job : jobs)
  {
    try
    {
      computeNormals(cl, job);
    }
    catch (const std::exception& e) // anything about this MESH: the others still run
    {
      reportProblem("normals", e.what());
      ++failed;
    }
  }
  return failed ? 1 : 0;
}

const CommandRegistration registration{ { 20, "normals",
  "compute vertex and face normals (weighting, sharp edges, orientation)", &runNormals } };
} // namespace

} // namespace app
} // namespace shadelab
