// shadelab lobe: a BRDF lobe and its polar slice, lobes on a mesh, or the albedo table.
#include "CommandLine.h"
#include "Commands.h"
#include "Inputs.h"
#include "LightingOptions.h"
#include "OutputFormats.h"

#include "shadelab/AtomicFile.h"
#include "shadelab/Scene.h"
#include "slAlbedoTable.h"
#include "slBRDFLobeSource.h"
#include "slLobeImageRenderer.h"
#include "slLobesOnMesh.h"
#include "slScene.h"
#include "slSceneRenderer.h"
#include "slUpdateOrThrow.h"

#include <vtkAbstractArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkTable.h>

#include <iostream>
#include <cctype>
#include <sstream>

namespace shadelab
{
namespace app
{

namespace
{
int modelNumber(const CommandLine& cl)
{
  return static_cast<int>(cl.has("model") ? parseModelOption("model", cl.get("model")) : ShadingModel::Phong);
}

/// --shininess, --incidence, --kd, --ks and --cosine onto a lobe source.
void applyLobeOptions(const CommandLine& cl, slBRDFLobeSource* lobe)
{
  lobe->SetShininess(cl.getNumber("shininess", 20.0, 0.0, 1e4));
  lobe->SetIncidenceAngle(cl.getNumber("incidence", 45.0, 0.0, 90.0));
  lobe->SetDiffuseWeight(cl.getNumber("kd", 0.0, 0.0, 1e3));
  lobe->SetSpecularWeight(cl.getNumber("ks", 1.0, 0.0, 1e3));
  lobe->SetMultiplyByCosine(cl.has("cosine"));
}

/// The albedo table as CSV, written all-or-nothing.
void writeTable(vtkTable* table, const std::string& path)
{
  std::ostringstream csv;
  csv.precision(6);
  for (vtkIdType c = 0; c < table->GetNumberOfColumns(); ++c)
  {
    csv << (c ? "," : "") << table->GetColumnName(c);
  }
  csv << "\n";
  for (vtkIdType r = 0; r < table->GetNumberOfRows(); ++r)
  {
    for (vtkIdType c = 0; c < table->GetNumberOfColumns(); ++c)
    {
      csv << (c ? "," : "") << table->GetValue(r, c).ToDouble();
    }
    csv << "\n";
  }
  writeFileAtomically(path, csv.str());
}

std::vector<OptionSpec> lobeOptions()
{
  std::vector<OptionSpec> specs = litOptions();
  specs.push_back({ "shininess", "n", "N", "shininess n (single lobe and albedo table; default 20)" });
  specs.push_back({ "incidence", "", "DEG", "angle of incidence from the normal (single lobe; default 45)" });
  specs.push_back({ "kd", "", "X", "k_d (single lobe; default 0)" });
  specs.push_back({ "ks", "", "X", "k_s (single lobe; default 1)" });
  specs.push_back({ "cosine", "", "", "multiply the lobe by cos(theta_o)" });
  specs.push_back({ "slice", "", "FILE", "also write the polar slice in the plane of incidence (single lobe)" });
  specs.push_back({ "points", "", "N", "lobes on MESH: number of sampled points (default 16)" });
  specs.push_back({ "light", "l", "INDEX", "lobes on MESH: the light giving the incident direction" });
  specs.push_back({ "scale", "", "X", "lobes on MESH: largest lobe / bounding-box diagonal (default 0.1)" });
  specs.push_back({ "albedo-table", "", "", "write the directional albedo table of every model (CSV)" });
  specs.push_back({ "models", "", "A,B,...", "single lobe as an image: overlay these models (default: --model)" });
  return specs;
}
} // namespace

namespace
{
int runLobe(const std::vector<std::string>& args)
{
  const std::vector<OptionSpec> specs = lobeOptions();
  const CommandLine cl(args, specs);
  if (cl.has("help"))
  {
    std::cout << "usage: shadelab lobe [--model M] [--incidence DEG] -o LOBE.vtp [--slice SLICE.vtp]\n"
                 "       shadelab lobe [--models A,B,...] [--incidence DEG] -o LOBE.png   (3D lobe, polar plot, albedo)\n"
                 "       shadelab lobe MESH [--scene S.json] [--points N] -o LOBES.vtp|LOBES.png\n"
                 "       shadelab lobe --albedo-table [--shininess N] -o TABLE.csv\n\n"
                 "A BRDF lobe r(w_o) = f_r(w_i, w_o) (optionally x cos theta_o) around +z, lobes on a\n"
                 "mesh in each point's normal frame lit by the scene's light, or the directional albedo\n"
                 "of every model against the angle of incidence.\n\noptions:\n"
              << CommandLine::describe(specs);
    return 0;
  }
  if (!cl.has("output"))
  {
    throw UsageError("missing -o/--output FILE");
  }
  const std::string output = cl.get("output");
  // The table is CSV; otherwise the extension chooses between a mesh and an image.
  const OutputKind kind = cl.has("albedo-table") ? checkOutputName(output, { OutputKind::Table })
                                                 : checkOutputName(output, { OutputKind::Mesh, OutputKind::Image });
  checkOutputOption(cl, "slice", { OutputKind::Mesh });
  if (cl.has("albedo-table"))
  {
    vtkNew<slAlbedoTable> table;
    table->SetShininess(cl.getNumber("shininess", 20.0, 0.0, 1e4));
    slUpdateOrThrow(table);
    writeTable(table->GetOutput(), output);
  }
  else if (cl.positional().empty() && kind == OutputKind::Image)
  {
    // One image: the 3D lobes, the polar slice and the albedo curves.
    vtkNew<slLobeImageRenderer> image;
    std::istringstream names(cl.get("models", modelName(static_cast<ShadingModel>(modelNumber(cl)))));
    for (std::string name; std::getline(names, name, ',');)
    {
      if (!image->AddModel(modelName(parseModelOption("models", name))))
      {
        throw UsageError("--models: at most six models can be overlaid");
      }
    }
    applyLobeOptions(cl, image->GetLobeParameters());
    slCallOrThrow(image, [&] { return image->Render(); }, output + ": ");
    writeImage(image->GetImage(), output);
  }
  else if (cl.positional().empty())
  {
    vtkNew<slBRDFLobeSource> lobe;
    lobe->SetModel(modelNumber(cl));
    applyLobeOptions(cl, lobe);
    slUpdateOrThrow(lobe);
    writeMesh(lobe->GetOutput(0), output, cl);
    if (cl.has("slice"))
    {
      writeMesh(lobe->GetSliceOutput(), cl.get("slice"), cl);
      std::cout << "wrote " << cl.get("slice") << "\n";
    }
  }
  else
  {
    const std::string meshPath = cl.meshWithOutput();
    vtkNew<slLobesOnMesh> lobes;
    vtkSmartPointer<slScene> scene = configureLitFilter(cl, lobes);
    lobes->SetNumberOfLobes(static_cast<int>(cl.getNumber("points", 16, 1, 100000)));
    lobes->SetLightIndex(cl.getIndex("light", -1, -1, 1000000));
    lobes->SetScale(cl.getNumber("scale", 0.1, 0.0, 100.0));
    lobes->SetMultiplyByCosine(cl.has("cosine"));
    vtkSmartPointer<vtkPolyData> mesh = loadMeshWithNormals(meshPath);
    lobes->SetInputData(mesh);
    runLitFilter(lobes, meshPath);
    if (lobes->GetNumberOfLobesDrawn() < lobes->GetNumberOfLobes())
    {
      std::cout << "drew " << lobes->GetNumberOfLobesDrawn() << " lobes: only that many points of " << meshPath
                << " face the light\n";
    }
    if (kind == OutputKind::Image)
    {
      // The lit mesh with its lobes, in orange, through ShadeLab's lighting pass.
      vtkNew<slSceneRenderer> renderer;
      renderer->SetScene(scene);
      renderer->SetMesh(mesh);
      renderer->AddOverlay(lobes->GetOutput(), 1.0, 0.55, 0.1);
      slCallOrThrow(renderer, [&] { return renderer->Render(); }, output + ": ");
      writeImage(renderer->GetImage(), output);
    }
    else
    {
      writeMesh(lobes->GetOutput(), output, cl);
    }
  }
  std::cout << "wrote " << output << "\n";
  return 0;
}

const CommandRegistration registration{ { 32, "lobe",
  "BRDF lobes (alone or on a mesh) and the directional albedo table", &runLobe } };
} // namespace

} // namespace app
} // namespace shadelab
