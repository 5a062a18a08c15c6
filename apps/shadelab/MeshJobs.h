#ifndef shadelab_app_MeshJobs_h
#define shadelab_app_MeshJobs_h
/**
 * @file MeshJobs.h
 * @brief The (input, output) pairs of a subcommand that maps meshes to
 * meshes, so that a batch pays the program's start-up once.
 *
 * `shadelab normals a.obj -o a.vtp` is one job. When -o names an existing
 * folder, every MESH argument is a job writing FOLDER/STEM.EXT, with EXT
 * from --format (default vtp): `shadelab normals a.obj b.ply -o out/`.
 */

#include "CommandLine.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace shadelab
{
namespace app
{

struct MeshJob
{
  std::string input;
  std::string output;
};

/// The --help paragraph on batches, ending in a newline.
const char* meshJobsHelp();

/// @p specs with -o/--output taking a mesh file or a folder (OUT) and the
/// --format option of a batch after it.
std::vector<OptionSpec> withMeshJobOptions(std::vector<OptionSpec> specs);

/// The jobs of the MESH arguments and -o of @p cl. Throws UsageError: no
/// MESH or no -o; several MESH arguments and -o not an existing folder;
/// --format without a folder, or not a mesh format; two MESH arguments that
/// would write the same file.
std::vector<MeshJob> meshJobs(const CommandLine& cl);

/// The file @p path names, to tell whether two outputs are one file: made
/// absolute, with "." and ".." resolved and existing symbolic links followed.
std::string outputIdentity(const std::string& path);

/// A UsageError "A and B would both write PATH" if two of @p outputs, each
/// (what writes it, its path), name one file by outputIdentity(): the
/// second write would replace the first.
void checkDistinctOutputs(const std::vector<std::pair<std::string, std::string>>& outputs);

/// A UsageError if option @p option of @p cl, which names one file for one
/// MESH (such as --image), is given for a batch of several.
void checkSingleMeshOption(const CommandLine& cl, const std::string& option, const std::vector<MeshJob>& jobs);

/// Runs @p work, a command's work on the mesh @p input, so that what it
/// cannot finish for want of memory is a shadelab::Error naming @p input:
/// "INPUT: out of memory (STEP)" for an OutOfMemory (Inputs.h), "INPUT: out
/// of memory" for another std::bad_alloc, and "INPUT: WHAT" for any other
/// std::exception but shadelab::Error and UsageError (a thread that cannot
/// start: "pthread_create has failed: ..."). Those two pass as they are.
void runOnMesh(const std::string& input, const std::function<void()>& work);

/// Runs @p run for each of @p jobs, each through runOnMesh(), and returns the
/// exit status. One job runs as it is: its problem ends the command. Of
/// several, one that fails is reported in its line ("shadelab COMMAND:
/// PROBLEM") and the others still run; the status is then 1.
int runMeshJobs(const std::string& command, const std::vector<MeshJob>& jobs,
  const std::function<void(const MeshJob&)>& run);

} // namespace app
} // namespace shadelab

#endif
