#include "MeshJobs.h"

#include "OutputFormats.h"

#include <filesystem>
#include <map>

namespace shadelab
{
namespace app
{

OptionSpec meshFormatOption()
{
  return { "format", "", "EXT",
    std::string("with -o FOLDER: the format of each output, FOLDER/NAME.EXT (") + outputExtensions(OutputKind::Mesh) +
      "; default vtp)" };
}

std::vector<MeshJob> meshJobs(const CommandLine& cl)
{
  const std::vector<std::string>& meshes = cl.positional();
  if (meshes.empty())
  {
    throw UsageError("expected a MESH argument");
  }
  if (!cl.has("output"))
  {
    throw UsageError("missing -o/--output FILE");
  }
  const std::string output = cl.get("output");
  std::error_code ignored;
  if (!std::filesystem::is_directory(output, ignored))
  {
    if (meshes.size() > 1)
    {
      throw UsageError("-o/--output: with " + std::to_string(meshes.size()) + " MESH arguments, \"" + output +
        "\" must be an existing folder");
    }
    if (cl.has("format"))
    {
      throw UsageError("--format: only with -o FOLDER (\"" + output + "\" is not a folder)");
    }
    checkOutputName(output, { OutputKind::Mesh });
    return { { meshes[0], output } };
  }
  std::string extension = cl.get("format", "vtp");
  if (!extension.empty() && extension[0] == '.')
  {
    extension.erase(0, 1);
  }
  checkOutputName("--format ." + extension, { OutputKind::Mesh });
  std::vector<MeshJob> jobs;
  std::map<std::string, std::string> writers; // output -> the input that writes it
  for (const std::string& mesh : meshes)
  {
    const std::string path =
      (std::filesystem::path(output) / std::filesystem::path(mesh).stem()).string() + "." + extension;
    const auto [at, added] = writers.emplace(path, mesh);
    if (!added)
    {
      throw UsageError(at->second + " and " + mesh + " would both write " + path);
    }
    jobs.push_back({ mesh, path });
  }
  return jobs;
}

} // namespace app
} // namespace shadelab
