// shadelab reference MESH [--scene S.json] [--envmap SKY.hdr] -o OUT.vtp
#include "BaseColourOptions.h"
#include "CommandLine.h"
#include "Commands.h"
#include "Inputs.h"
#include "LightingOptions.h"
#include "MaterialOptions.h"
#include "MeshJobs.h"
#include "OutputFormats.h"

#include "slRadianceReference.h"
#include "slScene.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <cstdio>
#include <iostream>

namespace shadelab
{
namespace app
{

namespace
{
int strategyNumber(const std::string& name)
{
  const char* names[] = { "uniform", "cosine", "brdf", "light", "mis" };
  for (int i = 0; i < 5; ++i)
  {
    if (name == names[i])
    {
      return i;
    }
  }
  throw UsageError("--sampling: \"" + name + "\" is not one of uniform, cosine, brdf, light, mis");
}

void printSummary(vtkPolyData* out)
{
  for (const char* name : { "RadianceErrorMean", "RadianceErrorRMS", "RadianceErrorMaxAbs", "MeanStdError" })
  {
    vtkDataArray* a = out->GetFieldData()->GetArray(name);
    if (a)
    {
      std::printf("%-20s %.6g %.6g %.6g\n", name, a->GetComponent(0, 0), a->GetComponent(0, 1), a->GetComponent(0, 2));
    }
  }
}

int runReference(const std::vector<std::string>& args)
{
  std::vector<OptionSpec> specs = withMaterialOptions(litOptions(), "default: the scene's");
  specs.push_back({ "envmap", "e", "FILE", "equirectangular HDR environment map (.hdr, .exr)" });
  specs.push_back({ "envmap-scale", "", "X", "multiply the environment's radiance (default 1)" });
  specs.push_back({ "no-lights", "", "", "do not use the scene's lights (environment only)" });
  specs.push_back({ "sampling", "", "NAME", "uniform, cosine, brdf, light or mis (default mis)" });
  specs.push_back({ "samples", "n", "N", "samples per point (default 64)" });
  specs.push_back({ "seed", "", "N", "random seed (default 1)" });
  specs.push_back({ "light-radius", "", "X", "radius of point/spot lights (default 1% of the mesh diagonal)" });
  specs.push_back({ "sun-angle", "", "DEG", "angular radius of directional lights (default 0.5)" });
  for (const OptionSpec& spec : baseColourOptions())
  {
    specs.push_back(spec);
  }
  const CommandLine cl(args, specs);
  if (cl.has("help"))
  {
    std::cout << "usage: shadelab reference MESH [--scene S.json] [--envmap SKY.hdr] -o OUT.vtp\n\n"
                 "Monte Carlo estimate per point of L_o = L_e + integral of f_r L_i cos(theta), lit by an\n"
                 "environment map and/or the scene's lights as small spherical lights. Writes Radiance,\n"
                 "RadianceStdError, DiscreteRadiance and RadianceError (reference - discrete) and prints\n"
                 "summary statistics of the error. The base colour that multiplies k_a and k_d is chosen as\n"
                 "in light: --diffuse-array, --diffuse-texture, or the scene's material.diffuseTexture (which\n"
                 "leaves a mesh without texture coordinates untextured).\n"
                 "MESH: " << meshFormatsText() << "; point normals are computed if missing.\n\noptions:\n"
              << CommandLine::describe(specs);
    return 0;
  }
  const std::string meshPath = cl.meshWithOutput();
  checkOutputOption(cl, "output", { OutputKind::Mesh });
  checkFieldImageOptions(cl, { { meshPath, cl.get("output") } });
  // Each of these shapes a light source the command would not use.
  if (cl.has("envmap-scale") && !cl.has("envmap"))
  {
    throw UsageError("--envmap-scale: only with --envmap FILE");
  }
  for (const char* option : { "light-radius", "sun-angle" })
  {
    if (cl.has(option) && cl.has("no-lights"))
    {
      throw UsageError(std::string("--") + option + ": the scene's lights are left out (--no-lights)");
    }
  }
  // The filter reads 0 as "1% of the mesh diagonal"; given, a radius is a size.
  if (cl.has("light-radius") && cl.getNumber("light-radius", 0.0, 0.0, 1e30) == 0.0)
  {
    throw UsageError("--light-radius: 0 is no sphere; give a radius above 0 (or leave it out for 1% of the mesh diagonal)");
  }
  checkBaseColourOptions(cl);
  vtkNew<slRadianceReference> filter;
  vtkSmartPointer<slScene> scene = configureLitFilter(cl, filter);
  if (cl.has("envmap"))
  {
    filter->SetEnvironmentFileName(cl.get("envmap").c_str());
  }
  filter->SetEnvironmentScale(cl.getNumber("envmap-scale", 1.0, 0.0, 1e6));
  filter->SetUseSceneLights(!cl.has("no-lights"));
  filter->SetStrategy(strategyNumber(cl.get("sampling", "mis")));
  filter->SetSamplesPerPoint(cl.getIndex("samples", 64, 1, 1 << 24));
  filter->SetSeed(cl.getIndex("seed", 1, 0, 2147483647));
  filter->SetLightRadius(cl.getNumber("light-radius", 0.0, 0.0, 1e30));
  filter->SetDirectionalLightAngle(cl.getNumber("sun-angle", 0.5, 1e-4, 45.0));
  // As light takes it, so that DiscreteRadiance is light's Radiance.
  const BaseColour base(cl, scene);
  runOnMesh(meshPath, [&] {
    vtkSmartPointer<vtkPolyData> mesh = loadMeshWithNormals(meshPath);
    base.applyTo(filter, mesh);
    filter->SetInputData(mesh);
    runLitFilter(filter, meshPath);
    writeFieldImageIfAsked(
      cl, filter->GetOutput(), scene, "Radiance,DiscreteRadiance,RadianceError,RadianceStdError", cl.get("output"));
    writeMesh(filter->GetOutput(), cl.get("output"), cl);
    printSummary(filter->GetOutput());
    std::cout << "wrote " << cl.get("output") << "\n";
  });
  return 0;
}

const CommandRegistration registration{ { 33, "reference",
  "Monte Carlo reference of the radiance equation and its error against discrete lights", &runReference } };
} // namespace

} // namespace app
} // namespace shadelab
