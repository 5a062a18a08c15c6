// shadelab compare MESH [--scene S.json] -o OUT.png [--models | --grid A,B,...] [--diff]
#include "CommandLine.h"
#include "Commands.h"
#include "Inputs.h"
#include "OutputFormats.h"

#include "shadelab/Scene.h"
#include "slComparisonRenderer.h"
#include "slLightingPass.h"
#include "slOffscreen.h"
#include "slScene.h"
#include "slUpdateOrThrow.h"

#include <vtkNew.h>
#include <vtkPolyData.h>

#include <iostream>
#include <string>

namespace shadelab
{
namespace app
{
namespace
{
int runCompare(const std::vector<std::string>& args)
{
  const std::vector<OptionSpec> specs{
    sceneOption(),
    { "output", "o", "FILE", outputHelp("composite image to write", OutputKind::Image) },
    { "models", "", "", "compare Lambert | Phong | Blinn-Phong (at the scene's frequency) instead of frequencies" },
    { "grid", "", "A,B,...", "draw these lighting models (or all) at the scene's frequency instead of frequencies" },
    { "columns", "", "N", "panels per row (default: one row; 4 with --grid)" },
    { "diff", "", "", "add a panel with the difference of the last two panels, amplified" },
    { "amplify", "", "X", "with --diff: amplification of the difference panel (default 8)" },
    { "size", "", "WxH", "size of each panel (default 400x300)" },
    { "help", "h", "", "show this help" },
  };
  const CommandLine cl(args, specs);
  if (cl.printHelpIfAsked("shadelab compare MESH [--scene S.json] -o OUT.png [--models | --grid A,B,...] [--diff]",
        "Renders MESH flat | Gouraud | Phong (or, with --models, Lambert | Phong | Blinn-Phong;\n"
        "with --grid, the models named, or all of them) side by side with one shared camera\n"
        "and labels, optionally with the amplified difference of the last two panels, and\n"
        "writes one composite image.\n\nLighting models: " +
          modelNameList() + ".",
        specs))
  {
    return 0;
  }
  const std::string meshPath = cl.meshWithOutput();
  checkOutputOption(cl, "output", { OutputKind::Image });
  int width = 400, height = 300;
  if (cl.has("size"))
  {
    parseSize(cl.get("size"), width, height);
  }
  const double amplify = cl.getNumber("amplify", 8.0, 1.0, 1000.0);
  if (cl.has("amplify") && !cl.has("diff"))
  {
    throw UsageError("--amplify: only with --diff");
  }
  if (cl.has("grid") && cl.has("models"))
  {
    throw UsageError("--grid: give either --grid or --models");
  }
  const std::vector<ShadingModel> grid =
    cl.has("grid") ? parseModelList("grid", cl.get("grid"), true) : std::vector<ShadingModel>();
  const int columns = cl.getIndex("columns", grid.empty() ? 0 : 4, 1, 64);
  const int panels = grid.empty() ? 3 : static_cast<int>(grid.size()); // --models and the frequencies: 3
  if (cl.has("diff") && panels < 2)
  {
    throw UsageError("--diff: needs two panels to compare (--grid names " + std::to_string(panels) + ")");
  }

  vtkNew<slComparisonRenderer> comparison;
  comparison->SetPanelWidth(width);
  comparison->SetPanelHeight(height);
  comparison->SetColumns(columns);
  // Refused before any work: beyond the largest image, nothing is drawn.
  const int cells = panels + (cl.has("diff") ? 1 : 0);
  int imageWidth = 0, imageHeight = 0;
  comparison->GetCompositeSize(cells, imageWidth, imageHeight);
  if (!slWindowSizeProblem(imageWidth, imageHeight).empty())
  {
    throw UsageError("--size: " + std::to_string(cells) + " panels of " + std::to_string(width) + "x" +
      std::to_string(height) + ", " + std::to_string(imageWidth / width) +
      " a row, make a " + std::to_string(imageWidth) + "x" + std::to_string(imageHeight) +
      " image; at most " + std::to_string(slMaximumWindowSize) + "x" + std::to_string(slMaximumWindowSize) +
      " can be rendered");
  }

  vtkSmartPointer<slScene> scene = loadScene(cl.get("scene"));
  const std::string lightProblem = slLightingPass::GetLightCountProblem(scene->GetNumberOfLights());
  if (!lightProblem.empty())
  {
    throw Error(cl.get("scene") + ": " + lightProblem);
  }
  vtkSmartPointer<vtkPolyData> mesh = loadMesh(meshPath);
  if (!grid.empty())
  {
    for (const ShadingModel model : grid)
    {
      checkTangentsFor(model, mesh, meshPath);
    }
  }
  else if (!cl.has("models")) // the frequency panels draw the scene's model
  {
    checkTangentsFor(scene, mesh, meshPath);
  }

  comparison->SetScene(scene);
  comparison->SetMesh(mesh);
  const std::string model = scene->GetModelName();
  const std::string frequency = scene->GetFrequencyName();
  if (!grid.empty())
  {
    for (const ShadingModel m : grid)
    {
      comparison->AddPanel(modelName(m), modelName(m), frequency.c_str());
    }
  }
  else if (cl.has("models"))
  {
    comparison->AddPanel("Lambert", "lambert", frequency.c_str());
    comparison->AddPanel("Phong", "phong", frequency.c_str());
    comparison->AddPanel("Blinn-Phong", "blinn-phong", frequency.c_str());
  }
  else
  {
    comparison->AddPanel("flat", model.c_str(), "flat");
    comparison->AddPanel("Gouraud", model.c_str(), "gouraud");
    comparison->AddPanel("Phong", model.c_str(), "phong");
  }
  if (cl.has("diff"))
  {
    comparison->SetDifference(panels - 2, panels - 1, amplify); // the last two, as --help says
  }
  slCallOrThrow(comparison, [&] { return comparison->Render(); });
  writeImage(comparison->GetImage(), cl.get("output"));
  std::cout << "wrote " << cl.get("output") << "\n";
  return 0;
}

const CommandRegistration registration{ { 11, "compare",
  "flat | Gouraud | Phong, or lighting models, side by side in one image", &runCompare } };
} // namespace
} // namespace app
} // namespace shadelab
