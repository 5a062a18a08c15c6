#include "MeshJobs.h"

#include "Commands.h"
#include "Inputs.h"
#include "OutputFormats.h"

#include <filesystem>
#include <map>

namespace shadelab
{
namespace app
{

const char* meshJobsHelp()
{
  return "With -o FOLDER, each MESH is written to FOLDER/NAME.EXT; a MESH that fails is\n"
         "reported and the others are still done (exit status 1 if any failed).\n";
}

std::vector<OptionSpec> withMeshJobOptions(std::vector<OptionSpec> specs)
{
  for (auto at = specs.begin(); at != specs.end(); ++at)
  {
    if (at->name == "output")
    {
      at->valueName = "OUT";
      at->help += ", or an existing folder";
      specs.insert(at + 1,
        { "format", "", "EXT",
          std::string("with -o FOLDER: the format of each output, FOLDER/NAME.EXT (") +
            outputExtensions(OutputKind::Mesh) + "; default vtp)" });
      break;
    }
  }
  return specs;
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
  std::vector<std::pair<std::string, std::string>> writers; // (input, the output it writes)
  for (const std::string& mesh : meshes)
  {
    const std::string path =
      (std::filesystem::path(output) / std::filesystem::path(mesh).stem()).string() + "." + extension;
    writers.emplace_back(mesh, path);
    jobs.push_back({ mesh, path });
  }
  checkDistinctOutputs(writers);
  return jobs;
}

std::string outputIdentity(const std::string& path)
{
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error);
  const std::filesystem::path identity = error ? absolute : std::filesystem::weakly_canonical(absolute, error);
  return error ? std::filesystem::path(path).lexically_normal().string() : identity.string();
}

void checkDistinctOutputs(const std::vector<std::pair<std::string, std::string>>& outputs)
{
  std::map<std::string, std::string> writers; // identity -> what writes it first
  for (const auto& [writer, path] : outputs)
  {
    const auto [at, added] = writers.emplace(outputIdentity(path), writer);
    if (!added)
    {
      throw UsageError(at->second + " and " + writer + " would both write " + path);
    }
  }
}

void checkSingleMeshOption(const CommandLine& cl, const std::string& option, const std::vector<MeshJob>& jobs)
{
  if (jobs.size() > 1 && cl.has(option))
  {
    throw UsageError("--" + option + ": only with one MESH (got " + std::to_string(jobs.size()) + ")");
  }
}

void runOnMesh(const std::string& input, const std::function<void()>& work)
{
  try
  {
    work();
  }
  catch (const Error&)
  {
    throw;
  }
  catch (const UsageError&)
  {
    throw;
  }
  catch (const OutOfMemory& e)
  {
    throw Error(input + ": out of memory (" + e.step() + ")");
  }
  catch (const std::exception& e)
  {
    throw Error(input + ": " + (isOutOfMemory(e) ? std::string("out of memory") : e.what()));
  }
}

int runMeshJobs(const std::string& command, const std::vector<MeshJob>& jobs,
  const std::function<void(const MeshJob&)>& run)
{
  if (jobs.size() == 1)
  {
    runOnMesh(jobs[0].input, [&] { run(jobs[0]); });
    return 0;
  }
  int failed = 0;
  for (const MeshJob& job : jobs)
  {
    try
    {
      runOnMesh(job.input, [&] { run(job); });
    }
    catch (const std::exception& e) // anything about this MESH: the others still run
    {
      reportProblem(command, e.what());
      ++failed;
    }
  }
  return failed ? 1 : 0;
}

} // namespace app
} // namespace shadelab
