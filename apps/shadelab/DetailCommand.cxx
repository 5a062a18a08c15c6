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
#include <sstream>

namespace shadelab
{
namespace app
{

namespace
{
/// "MIN to MAX" of a clamped property.
std::string rangeText(double low, double high)
{
  std::ostringstream text;
  text << low << " to " << high;
  return text.str();
}

int runDetail(const std::vector<std::string>& args)
{
  // The filters' own defaults and ranges (their vtkSetClampMacro), for the
  // help and the checks alike.
  vtkNew<slNormalMapFilter> normalMap;
  vtkNew<slBumpMapFilter> bumpMap;
  vtkNew<slDisplacementFilter> displacement;
  std::ostringstream strengthHelp, scaleHelp;
  strengthHelp << "normal-map strength, " << rangeText(normalMap->GetStrengthMinValue(), normalMap->GetStrengthMaxValue())
               << " (default " << normalMap->GetStrength() << ")";
  scaleHelp << "height scale: --bump-map " << rangeText(bumpMap->GetScaleMinValue(), bumpMap->GetScaleMaxValue())
            << " (default " << bumpMap->GetScale() << "), --displace "
            << rangeText(displacement->GetScaleMinValue(), displacement->GetScaleMaxValue()) << " (default "
            << displacement->GetScale() << ")";
  const std::vector<OptionSpec> specs{
    { "output", "o", "FILE", outputHelp("mesh to write", OutputKind::Mesh) },
    meshCompressionOption(),
    { "normal-map", "", "IMG", "tangent-space normal map (OpenGL, green up)" },
    { "directx", "", "", "the normal map is DirectX (green down)" },
    { "strength", "", "S", strengthHelp.str() },
    { "bump-map", "", "IMG", "height image: normals from its gradient" },
    { "displace", "", "IMG", "height image: move points along their normals" },
    { "scale", "", "S", scaleHelp.str() },
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
    slNormalMapFilter* f = normalMap;
    f->SetFileName(cl.get("normal-map").c_str());
    f->SetGreenDown(cl.has("directx"));
    f->SetStrength(cl.getNumber("strength", f->GetStrength(), f->GetStrengthMinValue(), f->GetStrengthMaxValue()));
    filter = f;
  }
  else if (cl.has("bump-map"))
  {
    slBumpMapFilter* f = bumpMap;
    f->SetFileName(cl.get("bump-map").c_str());
    f->SetScale(cl.getNumber("scale", f->GetScale(), f->GetScaleMinValue(), f->GetScaleMaxValue()));
    f->SetInvertHeight(cl.has("invert"));
    filter = f;
  }
  else
  {
    slDisplacementFilter* f = displacement;
    f->SetFileName(cl.get("displace").c_str());
    f->SetScale(cl.getNumber("scale", f->GetScale(), f->GetScaleMinValue(), f->GetScaleMaxValue()));
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
