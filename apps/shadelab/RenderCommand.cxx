// shadelab render MESH [--scene S.json] -o OUT.png
#include "CommandLine.h"
#include "Commands.h"
#include "Inputs.h"
#include "MaterialOptions.h"
#include "MeshJobs.h"
#include "OutputFormats.h"

#include "slImageWriter.h"
#include "slLightingPass.h"
#include "slScene.h"
#include "slSceneRenderer.h"
#include "slUpdateOrThrow.h"

#include "shadelab/BrdfFile.h"

#include <vtkNew.h>
#include <vtkPolyData.h>

#include <filesystem>
#include <iostream>
#include <sstream>

namespace shadelab
{
namespace app
{

namespace
{
/// --brdf and --param into the scene: --brdf replaces the scene's .brdf file
/// (its parameters then start from the file's defaults), --param sets values
/// on top of the scene's.
void applyBrdfOptions(const CommandLine& cl, slScene* scene)
{
  if (!cl.has("brdf") && !cl.has("param"))
  {
    return;
  }
  if (cl.has("vtk-lighting"))
  {
    throw UsageError("--brdf and --param need ShadeLab's pass: leave out --vtk-lighting");
  }
  shadelab::Scene s = scene->GetScene();
  if (cl.has("brdf"))
  {
    if (cl.get("brdf").empty())
    {
      throw UsageError("--brdf: needs a .brdf file");
    }
    // Relative to the working directory, not to a scene file's folder.
    s.brdf.file = s.sourceFile.empty() ? cl.get("brdf") : std::filesystem::absolute(cl.get("brdf")).string();
    s.brdf.parameters.clear();
  }
  else if (s.brdf.file.empty())
  {
    throw UsageError("--param: needs --brdf FILE (or a scene with a \"brdf\")");
  }
  for (const auto& option : cl.ordered())
  {
    if (option.first == "param")
    {
      s.brdf.parameters.push_back(option.second);
    }
  }
  // Read now, so that a bad file or value fails before anything is rendered.
  const shadelab::BrdfFile file = shadelab::readBrdfFile(cl.has("brdf") ? s.brdf.file : scene->GetBrdfFilePath());
  shadelab::brdfParameterValues(file, s.brdf.parameters);
  scene->SetScene(s);
}

/// The component view asked for on the command line, checked before
/// anything is read.
struct ComponentOptions
{
  int component = slLightingPass::TOTAL;
  int light = -1; ///< -1: every light
  bool falseColor = false;
};

/// Reads --component, --light and --false-color. Each is refused (UsageError)
/// where the image would not show it: with --vtk-lighting (only ShadeLab's
/// pass draws components), --light and --false-color without a component
/// view, --light with total or emission (no single light's part).
ComponentOptions parseComponentOptions(const CommandLine& cl)
{
  static const char* const names[] = { "total", "ambient", "diffuse", "specular", "emission", "cos" };
  constexpr int count = static_cast<int>(sizeof(names) / sizeof(names[0]));
  // The names of the components for which @p show holds: "a, b or c".
  auto listOf = [](auto show, const char* last = " or ") {
    std::vector<std::string> shown;
    for (int i = 0; i < count; ++i)
    {
      if (show(i))
      {
        shown.emplace_back(names[i]);
      }
    }
    std::string text;
    for (size_t i = 0; i < shown.size(); ++i)
    {
      text += (i == 0 ? "" : i + 1 == shown.size() ? last : ", ") + shown[i];
    }
    return text;
  };
  auto perLight = [](int c) { return c != slLightingPass::TOTAL && c != slLightingPass::EMISSION; };
  auto view = [](int c) { return c != slLightingPass::TOTAL; };

  ComponentOptions options;
  for (const char* name : { "component", "light", "false-color" })
  {
    if (cl.has(name) && cl.has("vtk-lighting"))
    {
      throw UsageError(std::string("--") + name + ": only for ShadeLab's pass, not with --vtk-lighting");
    }
  }
  if (cl.has("component"))
  {
    const std::string name = cl.get("component");
    options.component = -1;
    for (int i = 0; i < count; ++i)
    {
      options.component = name == names[i] ? i : options.component;
    }
    if (options.component < 0)
    {
      throw UsageError("--component: \"" + name + "\" is not one of " + listOf([](int) { return true; }, ", "));
    }
  }
  if (cl.has("light"))
  {
    if (!perLight(options.component))
    {
      throw UsageError("--light: only with --component " + listOf(perLight));
    }
    // An index no scene can have in the pass (negative, or beyond
    // GetMaximumNumberOfLights()) is a usage error (2); one the scene lacks
    // is known only after reading it (runRender: 1, as cosine and lobe).
    options.light = cl.getIndex("light", 0, 0, slLightingPass::GetMaximumNumberOfLights() - 1);
  }
  if (cl.has("false-color"))
  {
    if (!view(options.component))
    {
      throw UsageError("--false-color: only with --component " + listOf(view));
    }
    options.falseColor = true;
  }
  return options;
}

void applyComponentOptions(const ComponentOptions& options, slLightingPass* pass)
{
  pass->SetComponent(options.component);
  pass->SetComponentLight(options.light);
  pass->SetFalseColor(options.falseColor);
}

int runRender(const std::vector<std::string>& args)
{
  const std::vector<OptionSpec> specs = withMaterialOptions({
    sceneOption(),
    { "output", "o", "FILE", outputHelp("image to write", OutputKind::Image) },
    { "size", "", "WxH", "image size in pixels (default: the scene's imageSize)" },
    { "model", "", "NAME", modelOptionHelp() },
    { "frequency", "", "NAME", "override the scene's shading frequency: flat, gouraud, phong" },
    { "component", "", "NAME", "show only: ambient, diffuse, specular, emission or cos (N.L); total (default): the whole equation" },
    { "light", "", "K", "with --component ambient, diffuse, specular or cos: only light K (0-based; cos uses light 0 by default)" },
    { "false-color", "", "", "with --component (not total): false colour instead of grey/RGB" },
    { "brdf", "", "FILE", "shade with a BRDF Explorer .brdf file's BRDF instead of the model's (replaces the scene's brdf)" },
    { "param", "", "NAME=VALUE", "a .brdf parameter's value (float, bool true/false/0/1, colour r,g,b); repeat for more" },
    { "vtk-lighting", "", "", "use VTK's built-in lighting instead of ShadeLab's pass (prints what it lacks)" },
    { "quiet", "q", "", "with --vtk-lighting: do not print what VTK's lighting cannot show" },
    { "help", "h", "", "show this help" },
  }, "default: the scene's");
  const CommandLine cl(args, specs);
  if (cl.printHelpIfAsked("shadelab render MESH [--scene S.json] [--brdf F.brdf [--param NAME=VALUE ...]] -o OUT.png",
        std::string("Renders MESH (") + meshFormatsText() +
          ") offscreen with ShadeLab's lighting pass (the scene's model, lights\n"
          "and shading frequency) and writes the image through OpenImageIO.\n"
          "Needs an X display: run under xvfb-run on a headless machine.",
        specs))
  {
    return 0;
  }
  const std::string meshPath = cl.meshWithOutput();
  checkOutputOption(cl, "output", { OutputKind::Image });
  const ComponentOptions components = parseComponentOptions(cl);

  vtkSmartPointer<slScene> scene = loadScene(cl.get("scene"));
  applySceneOverrides(cl, scene);
  applyBrdfOptions(cl, scene);
  // The pass would draw only its first lights, unlike the CPU filters. VTK's
  // own lighting (--vtk-lighting) takes the scene's lights as vtkLights.
  const std::string lightProblem = slLightingPass::GetLightCountProblem(scene->GetNumberOfLights());
  if (!cl.has("vtk-lighting") && !lightProblem.empty())
  {
    throw Error(cl.get("scene") + ": " + lightProblem);
  }
  // As cosine does: a light the scene does not have is an error, not a
  // background-only image.
  checkLightOption(cl, components.light, scene);
  int width = 0, height = 0;
  if (cl.has("size"))
  {
    parseSize(cl.get("size"), width, height);
  }
  runOnMesh(meshPath, [&] {
    vtkSmartPointer<vtkPolyData> mesh = loadMesh(meshPath);
    if (!cl.has("vtk-lighting"))
    {
      checkTangentsFor(scene, mesh, meshPath);
    }

    vtkNew<slSceneRenderer> renderer;
    renderer->SetUseShadeLabLighting(!cl.has("vtk-lighting"));
    applyComponentOptions(components, renderer->GetLightingPass());
    renderer->SetScene(scene);
    renderer->SetMesh(mesh);
    renderer->SetWidth(width);
    renderer->SetHeight(height);
    inStep("rendering", [&] { slCallOrThrow(renderer, [&] { return renderer->Render(); }); });
    if (cl.has("vtk-lighting") && !cl.has("quiet"))
    {
      std::istringstream notes(scene->GetConversionNotes());
      for (std::string line; std::getline(notes, line);)
      {
        std::cerr << "shadelab render: note: " << line << "\n";
      }
    }
    writeImage(renderer->GetImage(), cl.get("output"));
    std::cout << "wrote " << cl.get("output") << "\n";
  });
  return 0;
}

const CommandRegistration registration{ { 10, "render",
  "render a mesh with a scene offscreen and write an image", &runRender } };
} // namespace

} // namespace app
} // namespace shadelab
