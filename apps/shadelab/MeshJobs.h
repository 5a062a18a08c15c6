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

#include <string>
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

/// The --format option that names the output format of a batch.
OptionSpec meshFormatOption();

/// The jobs of the MESH arguments and -o of @p cl. Throws UsageError: no
/// MESH or no -o; several MESH arguments and -o not an existing folder;
/// --format without a folder, or not a mesh format; two MESH arguments that
/// would write the same file.
std::vector<MeshJob> meshJobs(const CommandLine& cl);

} // namespace app
} // namespace shadelab

#endif
