// shadelab detail MESH -o OUT (--normal-map IMG | --bump-map IMG | --displace IMG) [...]
#include "CommandLine.h"
#include "Commands.h"
#include "Inputs.h"
#include "MeshJobs.h"
#include "NormalsOptions.h"
#include "OutputFormats.h"

#include "slBumpMapFilter.h"
#include "slDisplacementFilter.h"
#include "slNormalMapFilter.h"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <iostream>

namespace shadelab
{
namespace app
{

namespace
{
int runDetail(const std::vector<std::string>& args)
{
  const std::vector<OptionSpec> specs{
    { "output", "o", "FILE", outputHelp("mesh to write", OutputKind::Mesh) },
    meshCompressionOption(),
    { "normal-map", "", "IMG", "tangent-space normal map (OpenGL, green up)" },
    { "directx", "", "", "the normal map is DirectX (green down)" },
    { "strength", "", "S", "normal-map strength, 0-10 (default 1)" },
    { "bump-map", "", "IMG", "height image: normals from its gradient" },
    { "displace", "", "IMG", "height image: move points along their normals" },
    { "scale", "", "S", "height scale for --bump-map / --displace (default 0.05)" },
    { "invert", "", "", "height = 1 - value (depth maps, e.g. Bevy's)" },
    { "help", "h", "", "show this help" },
  };
  const CommandLine cl(args, specs);
  if (cl.has("help"))
  {
    std::cout << "usage: shadelab detail MESH -o OUT (--normal-map IMG | --bump-map IMG | --displace IMG)\n\n"
                 "Adds surface detail to MESH ("
              << meshFormatsText()
              << ") through its texture coordinates: perturbed point normals\n"
                 "from a normal map or a bump (height) map, or points displaced by a height map.\n\noptions:\n"
              << CommandLine::describe(specs);
    return 0;
  }
  const std::string meshPath = cl.meshWithOutput();
  checkOutputOption(cl, "output", { OutputKind::Mesh });
  const int modes = cl.has("normal-map") + cl.has("bump-map") + cl.has("displace");
  if (modes != 1)
  {
    throw UsageError("give exactly one of --normal-map, --bump-map, --displace");
  }
  // Each of these options tunes some of the modes; with another it would do nothing.
  const bool height = cl.has("bump-map") || cl.has("displace");
  for (const char* option : { "directx", "strength" })
  {
    if (cl.has(option) && height)
    {
      throw UsageError(std::string("--") + option + ": only with --normal-map");
    }
  }
  for (const char* option : { "scale", "invert" })
  {
    if (cl.has(option) && !height)
    {
      throw UsageError(std::string("--") + option + ": only with --bump-map or --displace");
    }
  }
  vtkSmartPointer<slPolyDataFilter> filter;
  if (cl.has("normal-map"))
  {
    auto f = vtkSmartPointer<slNormalMapFilter>::New();
    f->SetFileName(cl.get("normal-map").c_str());
    f->SetGreenDown(cl.has("directx"));
    f->SetStrength(cl.getNumber("strength", 1.0, 0.0, 10.0));
    filter = f;
  }
  else if (cl.has("bump-map"))
  {
    auto f = vtkSmartPointer<slBumpMapFilter>::New();
    f->SetFileName(cl.get("bump-map").c_str());
    f->SetScale(cl.getNumber("scale", 0.05, -100.0, 100.0));
    f->SetInvertHeight(cl.has("invert"));
    filter = f;
  }
  else
  {
    auto f = vtkSmartPointer<slDisplacementFilter>::New();
    f->SetFileName(cl.get("displace").c_str());
    f->SetScale(cl.getNumber("scale", 0.05, -1e6, 1e6));
    f->SetInvertHeight(cl.has("invert"));
    filter = f;
  }
  const std::string& path = meshPath;
  runOnMesh(path, [&] {
    vtkSmartPointer<vtkPolyData> mesh = loadMesh(path);
    noteNonPolygonCells(mesh, "detail", path);
    filter->SetInputData(mesh);
    vtkSmartPointer<vtkPolyData> out = runMeshFilter(filter, path);
    writeMesh(out, cl.get("output"), cl);
    std::cout << "wrote " << cl.get("output") << ": " << out->GetNumberOfPoints() << " points\n";
  });
  return 0;
}

const CommandRegistration registration{ { 22, "detail",
  "normal maps, bump maps and displacement through a mesh's UVs", &runDetail } };
} // namespace

} // namespace app
} // namespace shadelab
