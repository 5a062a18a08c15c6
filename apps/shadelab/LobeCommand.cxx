// shadelab lobe: a BRDF lobe and its polar slice, lobes on a mesh, or the
// albedo table; built-in models and BRDF Explorer .brdf files.
#include "BrdfOptions.h"
#include "CommandLine.h"
#include "Commands.h"
#include "Inputs.h"
#include "LightingOptions.h"
#include "MaterialOptions.h"
#include "MeshJobs.h"
#include "OutputFormats.h"

#include "shadelab/AtomicFile.h"
#include "shadelab/BrdfFile.h"
#include "shadelab/LightingGLSL.h"
#include "shadelab/LightingTables.h"
#include "shadelab/Scene.h"
#include "slAlbedoTable.h"
#include "slBRDFFileEvaluator.h"
#include "slBRDFLobeSource.h"
#include "slLobeImageRenderer.h"
#include "slLobesOnMesh.h"
#include "slScene.h"
#include "slSceneRenderer.h"
#include "slUpdateOrThrow.h"

#include <vtkAbstractArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkTable.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>
#include <memory>
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

/// The models --models names ("all" when @p allowAll), else --model's.
std::vector<ShadingModel> chosenModels(const CommandLine& cl, bool allowAll)
{
  return parseModelList("models", cl.get("models", modelName(static_cast<ShadingModel>(modelNumber(cl)))), allowAll);
}

/// --theta-resolution and --phi-resolution onto @p lobes (slBRDFLobeSource
/// or slLobesOnMesh), each within the class's own range; not given, the
/// class's default.
template <typename Lobes>
void applyResolutionOptions(const CommandLine& cl, Lobes* lobes)
{
  lobes->SetThetaResolution(cl.getIndex("theta-resolution", lobes->GetThetaResolution(),
    lobes->GetThetaResolutionMinValue(), lobes->GetThetaResolutionMaxValue()));
  lobes->SetPhiResolution(cl.getIndex(
    "phi-resolution", lobes->GetPhiResolution(), lobes->GetPhiResolutionMinValue(), lobes->GetPhiResolutionMaxValue()));
}

/// The material numbers, --incidence, --kd, --ks, --cosine and the
/// resolutions onto a lobe source; the numbers not given keep the source's
/// defaults.
void applyLobeOptions(const CommandLine& cl, slBRDFLobeSource* lobe)
{
  applyResolutionOptions(cl, lobe);
  applyMaterialOptionsByKey(cl, lobe);
  lobe->SetIncidenceAngle(cl.getNumber("incidence", 45.0, 0.0, 90.0));
  // Not given: the model's unit weight (slBRDFLobeSource's -1).
  lobe->SetDiffuseWeight(cl.getNumber("kd", -1.0, 0.0, 1e3));
  lobe->SetSpecularWeight(cl.getNumber("ks", -1.0, 0.0, 1e3));
  lobe->SetMultiplyByCosine(cl.has("cosine"));
}

/// Throws UsageError for an --incidence at which the light grazes the
/// surface: slBRDF() is 0 there for every built-in model (it does not divide
/// by cos theta_i <= SL_MIN_COS_THETA), so their lobes would be empty. A
/// .brdf file's own GLSL decides for itself, so it may take 90 degrees.
void refuseGrazingIncidence(const CommandLine& cl)
{
  const double degrees = cl.getNumber("incidence", 45.0, 0.0, 90.0);
  if (std::cos(degrees * glsl::SL_PI / 180.0) <= glsl::SL_MIN_COS_THETA)
  {
    std::ostringstream text;
    text << "--incidence " << degrees
         << ": the light grazes the surface, where every built-in model's f_r is 0, so the lobe would be empty"
            " (below "
         << std::acos(glsl::SL_MIN_COS_THETA) * 180.0 / glsl::SL_PI << " degrees)";
    throw UsageError(text.str());
  }
}

/// Throws UsageError for an option of the built-in models when only .brdf
/// files are drawn: a file's f_r reads its own parameters (--param), so
/// --model, --kd, --ks and the material numbers would change nothing.
void refuseModelOptionsForFilesAlone(const CommandLine& cl)
{
  std::vector<std::string> names{ "model", "kd", "ks" };
  for (const MaterialParameterInfo& row : kMaterialParameters)
  {
    if (!row.colour)
    {
      names.push_back(materialOptionName(row.key));
    }
  }
  for (const std::string& name : names)
  {
    if (cl.has(name))
    {
      throw UsageError("--" + name +
        ": only for built-in models; a .brdf file's lobe takes the file's parameters (--param NAME=VALUE)");
    }
  }
}

/// The albedo table as CSV, written all-or-nothing, with 10 significant
/// digits: the built-in models' albedo is integrated to 1e-9 relative
/// (Albedo.h), which 6 digits would round away.
void writeTable(vtkTable* table, const std::string& path)
{
  std::ostringstream csv;
  csv.precision(10);
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

/// Reads each --brdf file with its --param values and compiles its shader:
/// a bad file or value is an error before any output is made.
std::vector<std::unique_ptr<slBRDFFileEvaluator>> loadBrdfFiles(const std::vector<BrdfChoice>& choices)
{
  std::vector<std::unique_ptr<slBRDFFileEvaluator>> evaluators;
  for (const BrdfChoice& choice : choices)
  {
    const BrdfFile file = readBrdfFile(choice.path);
    const std::vector<glm::vec3> values = brdfParameterValues(file, choice.overrides);
    evaluators.emplace_back(new slBRDFFileEvaluator(file, values));
  }
  return evaluators;
}

/// Prints each file's directional albedo at @p degrees of incidence.
void printAlbedos(const std::vector<std::string>& names, const std::vector<double>& albedos, double degrees)
{
  for (size_t i = 0; i < names.size() && i < albedos.size(); ++i)
  {
    std::cout << "albedo of " << names[i] << " at " << degrees << " degrees: " << albedos[i] << "\n";
  }
}

/// What `shadelab lobe` makes: each mode takes options of its own.
enum class LobeMode
{
  AlbedoTable, ///< --albedo-table -o TABLE.csv
  LobeImage,   ///< -o LOBE.png: lobes, polar plot and albedo of one or more BRDFs
  LobeMesh,    ///< -o LOBE.vtp: one lobe as a mesh
  LobesOnMesh, ///< MESH -o LOBES.vtp|LOBES.png
};

/// Throws UsageError for an option given in a mode that would ignore it.
void refuseOptionsOfOtherModes(const CommandLine& cl, LobeMode mode)
{
  using M = LobeMode;
  struct ModeOption
  {
    const char* name;
    std::vector<LobeMode> modes;
    const char* what; ///< the modes, as the message names them
  };
  static const ModeOption options[] = {
    { "incidence", { M::LobeImage, M::LobeMesh }, "a single lobe (-o LOBE.vtp or LOBE.png)" },
    { "kd", { M::LobeImage, M::LobeMesh }, "a single lobe (-o LOBE.vtp or LOBE.png)" },
    { "ks", { M::LobeImage, M::LobeMesh }, "a single lobe (-o LOBE.vtp or LOBE.png)" },
    { "cosine", { M::LobeImage, M::LobeMesh, M::LobesOnMesh }, "lobes, not with --albedo-table" },
    { "slice", { M::LobeMesh }, "a single lobe as a mesh (-o LOBE.vtp)" },
    { "models", { M::LobeImage, M::AlbedoTable }, "a single lobe as an image (-o LOBE.png) or --albedo-table" },
    { "angles", { M::AlbedoTable }, "--albedo-table" },
    { "points", { M::LobesOnMesh }, "lobes on MESH" },
    { "light", { M::LobesOnMesh }, "lobes on MESH" },
    { "scale", { M::LobesOnMesh }, "lobes on MESH" },
    { "scene", { M::LobesOnMesh }, "lobes on MESH (a single lobe takes --model and the material options)" },
    { "allow-zero-normals", { M::LobesOnMesh }, "lobes on MESH" },
  };
  for (const ModeOption& option : options)
  {
    if (cl.has(option.name) && std::find(option.modes.begin(), option.modes.end(), mode) == option.modes.end())
    {
      throw UsageError(std::string("--") + option.name + ": only for " + option.what);
    }
  }
}

std::vector<OptionSpec> lobeOptions()
{
  std::vector<OptionSpec> specs =
    withMaterialOptions(litOptions(), [](const shadelab::MaterialParameterInfo& row) {
      // A lone lobe's numbers are slBRDFLobeSource's own.
      vtkNew<slBRDFLobeSource> lone;
      std::ostringstream text;
      text << "default: the scene's with MESH, else " << lone->GetMaterialParameter(row.key);
      return text.str();
    });
  // --image and --fields draw the arrays of a lit mesh beside it; lobe draws
  // its own images (-o LOBE.png, -o LOBES.png), so they are not offered.
  specs.erase(std::remove_if(specs.begin(), specs.end(),
                [](const OptionSpec& spec) { return spec.name == "image" || spec.name == "fields"; }),
    specs.end());
  specs.push_back({ "incidence", "", "DEG", "angle of incidence from the normal (single lobe; default 45; below 90 for built-in models, whose f_r is 0 at grazing incidence)" });
  // The models whose unit weight is k_d (shadelab::unitWeights()).
  std::string diffuseOnly;
  for (const shadelab::LightingModelInfo& m : shadelab::kLightingModels)
  {
    if (shadelab::unitWeights(m.model).diffuse > 0.0f)
    {
      diffuseOnly += (diffuseOnly.empty() ? "" : ", ") + std::string(m.name);
    }
  }
  specs.push_back({ "kd", "", "X", "k_d (single lobe; default 1 for " + diffuseOnly + ", else 0)" });
  specs.push_back({ "ks", "", "X", "k_s (single lobe; default 0 for " + diffuseOnly + ", else 1)" });
  specs.push_back({ "cosine", "", "", "multiply the lobe by cos(theta_o)" });
  {
    // Each class's own default and range: a sharp lobe (a large shininess)
    // needs more rings than the default to show its peak.
    vtkNew<slBRDFLobeSource> one;
    vtkNew<slLobesOnMesh> many;
    auto help = [](const char* what, int oneValue, int oneLow, int oneHigh, int manyValue, int manyLow,
                  int manyHigh) {
      std::ostringstream text;
      text << what << " (single lobe: default " << oneValue << ", " << oneLow << " to " << oneHigh
           << "; lobes on MESH: default " << manyValue << ", " << manyLow << " to " << manyHigh << ")";
      return text.str();
    };
    specs.push_back({ "theta-resolution", "", "N",
      help("rings of the lobe from the normal to the horizon, and the slice's fineness", one->GetThetaResolution(),
        one->GetThetaResolutionMinValue(), one->GetThetaResolutionMaxValue(), many->GetThetaResolution(),
        many->GetThetaResolutionMinValue(), many->GetThetaResolutionMaxValue()) });
    specs.push_back({ "phi-resolution", "", "N",
      help("segments of the lobe around the normal", one->GetPhiResolution(), one->GetPhiResolutionMinValue(),
        one->GetPhiResolutionMaxValue(), many->GetPhiResolution(), many->GetPhiResolutionMinValue(),
        many->GetPhiResolutionMaxValue()) });
  }
  specs.push_back({ "slice", "", "FILE", "also write the polar slice in the plane of incidence (single lobe)" });
  specs.push_back({ "points", "", "N", "lobes on MESH: number of sampled points (default 16)" });
  specs.push_back({ "light", "l", "INDEX", "lobes on MESH: the light giving the incident direction (default: the first light that has one)" });
  specs.push_back({ "scale", "", "X", "lobes on MESH: largest lobe / bounding-box diagonal (default 0.1)" });
  specs.push_back({ "albedo-table", "", "", "write the directional albedo table of every model (CSV)" });
  {
    vtkNew<slAlbedoTable> table;
    std::ostringstream text;
    text << "albedo table: incidence angles from 0 to " << table->GetMaximumIncidence() << " degrees (default "
         << table->GetNumberOfAngles() << ", " << table->GetNumberOfAnglesMinValue() << " to "
         << table->GetNumberOfAnglesMaxValue() << ")";
    specs.push_back({ "angles", "", "N", text.str() });
  }
  specs.push_back({ "models", "", "A,B,...",
    "single lobe as an image: overlay these models (default: --model); albedo table: only these models' columns (default: --model, else all)" });
  for (const OptionSpec& spec : brdfOptionSpecs())
  {
    specs.push_back(spec);
  }
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
    std::cout << "usage: shadelab lobe [--model M | --brdf F.brdf [--param N=V ...]] [--incidence DEG] -o LOBE.vtp\n"
                 "           [--slice SLICE.vtp]\n"
                 "       shadelab lobe [--models A,B,...] [--brdf F.brdf [--param N=V ...] ...] [--incidence DEG]\n"
                 "           -o LOBE.png   (3D lobes, polar plot, albedo; at most six BRDFs)\n"
                 "       shadelab lobe MESH [--scene S.json] [--points N] -o LOBES.vtp|LOBES.png\n"
                 "       shadelab lobe --albedo-table [--models A,B,...] [--angles N] [--shininess N] [--roughness X ...]\n"
                 "           [--brdf F.brdf ...] -o TABLE.csv\n\n"
                 "A BRDF lobe r(w_o) = f_r(w_i, w_o) (optionally x cos theta_o) around +z, lobes on a\n"
                 "mesh in each point's normal frame lit by the scene's light, or the directional albedo\n"
                 "of every model against the angle of incidence. A BRDF Explorer .brdf file's BRDF is\n"
                 "evaluated on the GPU; its albedo is printed.\n\noptions:\n"
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
  if (cl.has("slice"))
  {
    checkDistinctOutputs({ { "-o/--output", output }, { "--slice", cl.get("slice") } });
  }
  const std::vector<BrdfChoice> brdfs = brdfChoices(cl);
  std::vector<std::string> brdfNames;
  for (const BrdfChoice& choice : brdfs)
  {
    brdfNames.push_back(brdfDisplayName(choice.path));
  }
  const bool imageOfLobes = cl.positional().empty() && kind == OutputKind::Image && !cl.has("albedo-table");
  if (!cl.positional().empty() && !brdfs.empty())
  {
    throw UsageError("--brdf: lobes on a mesh take the scene's model; a .brdf file's lobe is drawn alone");
  }
  const bool lobeMesh = cl.positional().empty() && !cl.has("albedo-table") && !imageOfLobes;
  refuseOptionsOfOtherModes(cl,
    cl.has("albedo-table") ? LobeMode::AlbedoTable
      : imageOfLobes       ? LobeMode::LobeImage
      : lobeMesh           ? LobeMode::LobeMesh
                           : LobeMode::LobesOnMesh);
  const bool drawsModels =
    (lobeMesh && brdfs.empty()) || (imageOfLobes && (cl.has("models") || cl.has("model") || brdfs.empty()));
  if (drawsModels)
  {
    refuseGrazingIncidence(cl);
  }
  else if (lobeMesh || imageOfLobes)
  {
    refuseModelOptionsForFilesAlone(cl);
  }
  if (lobeMesh && brdfs.size() > 1)
  {
    throw UsageError("--brdf: a lobe mesh takes one .brdf file; an image (-o LOBE.png) overlays several");
  }
  // Every file is read and compiled before anything is written.
  std::vector<std::unique_ptr<slBRDFFileEvaluator>> evaluators = loadBrdfFiles(brdfs);
  if (cl.has("albedo-table"))
  {
    vtkNew<slAlbedoTable> table;
    applyMaterialOptionsByKey(cl, table.GetPointer());
    table->SetNumberOfAngles(cl.getIndex(
      "angles", table->GetNumberOfAngles(), table->GetNumberOfAnglesMinValue(), table->GetNumberOfAnglesMaxValue()));
    if (cl.has("models") || cl.has("model"))
    {
      table->DisableAllModels();
      for (const ShadingModel model : chosenModels(cl, true))
      {
        table->SetModelEnabled(static_cast<int>(model), true);
      }
    }
    slUpdateOrThrow(table);
    vtkTable* out = table->GetOutput();
    vtkAbstractArray* degrees = out->GetColumnByName("IncidenceDegrees");
    for (size_t i = 0; i < evaluators.size(); ++i)
    {
      // The same file twice (other --param values): numbered columns, as a
      // table's column of an existing name would replace it.
      std::string name = brdfNames[i];
      for (int copy = 2; out->GetColumnByName(name.c_str()); ++copy)
      {
        name = brdfNames[i] + " (" + std::to_string(copy) + ")";
      }
      vtkNew<vtkDoubleArray> column;
      column->SetName(name.c_str());
      for (vtkIdType row = 0; row < degrees->GetNumberOfTuples(); ++row)
      {
        column->InsertNextValue(evaluators[i]->AlbedoAtIncidence(degrees->GetVariantValue(row).ToDouble()));
      }
      out->AddColumn(column);
    }
    writeTable(out, output);
  }
  else if (imageOfLobes)
  {
    // One image: the 3D lobes, the polar slice and the albedo curves.
    vtkNew<slLobeImageRenderer> image;
    if (cl.has("models") || cl.has("model") || brdfs.empty())
    {
      for (const ShadingModel model : chosenModels(cl, false))
      {
        if (!image->AddModel(modelName(model)))
        {
          throw UsageError("--models: at most six BRDFs (models and .brdf files) can be overlaid");
        }
      }
    }
    for (const BrdfChoice& choice : brdfs)
    {
      if (!image->AddBRDFFile(choice.path.c_str()))
      {
        throw UsageError("--brdf: at most six BRDFs (models and .brdf files) can be overlaid");
      }
      for (const std::string& o : choice.overrides)
      {
        image->AddBRDFFileParameter(o.c_str());
      }
    }
    applyLobeOptions(cl, image->GetLobeParameters());
    slCallOrThrow(image, [&] { return image->Render(); }, output + ": ");
    writeImage(image->GetImage(), output);
    std::vector<double> albedos;
    for (int i = 0; i < image->GetNumberOfBRDFFiles(); ++i)
    {
      albedos.push_back(image->GetBRDFFileAlbedo(i));
    }
    printAlbedos(brdfNames, albedos, image->GetLobeParameters()->GetIncidenceAngle());
  }
  else if (cl.positional().empty())
  {
    vtkNew<slBRDFLobeSource> lobe;
    lobe->SetModel(modelNumber(cl));
    applyLobeOptions(cl, lobe);
    if (!evaluators.empty())
    {
      evaluators[0]->SetLobeValues(lobe);
    }
    slUpdateOrThrow(lobe);
    if (!evaluators.empty())
    {
      printAlbedos(brdfNames, { evaluators[0]->AlbedoAtIncidence(lobe->GetIncidenceAngle()) },
        lobe->GetIncidenceAngle());
    }
    if (cl.has("slice"))
    {
      // A missing or read-only folder of either file fails here, before
      // anything is written; then the slice, as --image elsewhere, goes
      // before the main output, which a failed slice leaves as it was.
      checkOutputsCanBeCreated({ cl.get("slice"), output });
      writeMesh(lobe->GetSliceOutput(), cl.get("slice"), cl);
      std::cout << "wrote " << cl.get("slice") << "\n";
    }
    writeMesh(lobe->GetOutput(0), output, cl);
  }
  else
  {
    const std::string meshPath = cl.meshWithOutput();
    vtkNew<slLobesOnMesh> lobes;
    vtkSmartPointer<slScene> scene = configureLitFilter(cl, lobes);
    lobes->SetNumberOfLobes(static_cast<int>(cl.getNumber("points", 16, 1, 100000)));
    lobes->SetLightIndex(lightOption(cl, scene));
    lobes->SetScale(cl.getNumber("scale", 0.1, 0.0, 100.0));
    lobes->SetMultiplyByCosine(cl.has("cosine"));
    applyResolutionOptions(cl, lobes.Get());
    runOnMesh(meshPath, [&] {
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
        inStep("rendering", [&] { slCallOrThrow(renderer, [&] { return renderer->Render(); }, output + ": "); });
        writeImage(renderer->GetImage(), output);
      }
      else
      {
        writeMesh(lobes->GetOutput(), output, cl);
      }
    });
  }
  std::cout << "wrote " << output << "\n";
  return 0;
}

const CommandRegistration registration{ { 32, "lobe",
  "BRDF lobes (alone or on a mesh) and the directional albedo table", &runLobe } };
} // namespace

} // namespace app
} // namespace shadelab
