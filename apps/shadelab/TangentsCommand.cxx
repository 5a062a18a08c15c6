// shadelab tangents MESH -o OUT [normals options]
#include "CommandLine.h"
#include "Counted.h"
#include "Commands.h"
#include "Inputs.h"
#include "MeshJobs.h"
#include "NormalsOptions.h"
#include "OutputFormats.h"

#include "slPolyDataNormals.h"
#include "slPolyDataTangents.h"

#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <iostream>

namespace shadelab
{
namespace app
{

namespace
{
int runTangents(const std::vector<std::string>& args)
{
  std::vector<OptionSpec> specs{ { "output", "o", "FILE", outputHelp("mesh to write; .vtp and .vtk keep the Tangents array", OutputKind::Mesh) } };
  for (const OptionSpec& s : normalsOptionSpecs())
  {
    specs.push_back(s);
  }
  specs.push_back({ "help", "h", "", "show this help" });
  const CommandLine cl(args, specs);
  if (cl.has("help"))
  {
    std::cout << "usage: shadelab tangents MESH -o OUT [options]\n\n"
                 "Computes MikkTSpace-style tangent frames of MESH ("
              << meshFormatsText()
              << ") from its texture coordinates:\n"
                 "point array \"Tangents\" (xyz and handedness w = +-1, bitangent = w N x T).\n"
                 "When MESH has no normals they are computed first, as the normals options say;\n"
                 "MESH's own normals are kept (a normals option is then an error).\n\noptions:\n"
              << CommandLine::describe(specs);
    return 0;
  }
  const std::string meshPath = cl.meshWithOutput();
  checkOutputOption(cl, "output", { OutputKind::Mesh });
  vtkNew<slPolyDataNormals> normals;
  applyNormalsOptions(cl, normals);
  const std::string& path = meshPath;
  runOnMesh(path, [&] {
    vtkSmartPointer<vtkPolyData> mesh = loadMesh(path);
    noteNonPolygonCells(mesh, "tangents", path);
    if (!mesh->GetPointData()->GetNormals())
    {
      normals->SetInputData(mesh);
      mesh = runMeshFilter(normals, path);
    }
    else
    {
      // The mesh's own normals are kept: a normals option would change nothing.
      for (const OptionSpec& spec : normalsOptionSpecs())
      {
        if (cl.has(spec.name))
        {
          throw Error(path + ": --" + spec.name +
            ": the mesh has point normals, which tangents keep; the normals options apply only to a mesh without them");
        }
      }
    }
    vtkNew<slPolyDataTangents> tangents;
    tangents->SetInputData(mesh);
    vtkSmartPointer<vtkPolyData> out = runMeshFilter(tangents, path);
    writeMesh(out, cl.get("output"), cl);
    std::cout << "wrote " << cl.get("output") << ": " << counted(out->GetNumberOfPoints(), "point") << " ("
              << tangents->GetNumberOfSplitPoints() << " split along mirror seams)\n";
  });
  return 0;
}

const CommandRegistration registration{ { 21, "tangents",
  "compute tangent frames (MikkTSpace-style, with handedness) from UVs", &runTangents } };
} // namespace

} // namespace app
} // namespace shadelab
