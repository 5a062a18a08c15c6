#ifndef shadelab_app_BrdfOptions_h
#define shadelab_app_BrdfOptions_h
/**
 * @file BrdfOptions.h
 * @brief `--brdf FILE [--param NAME=VALUE ...]`, repeatable: BRDF Explorer
 * .brdf files and the overrides of their parameters, for the subcommands
 * that take them.
 */

#include "CommandLine.h"

#include <string>
#include <vector>

namespace shadelab
{
namespace app
{

/// One --brdf FILE and the --param NAME=VALUE options after it.
struct BrdfChoice
{
  std::string path;
  std::vector<std::string> overrides;
};

/// The option specs of --brdf and --param.
std::vector<OptionSpec> brdfOptionSpecs();

/// The --brdf options in command-line order, each with the --param options
/// that follow it (up to the next --brdf). UsageError for a --param before
/// any --brdf.
std::vector<BrdfChoice> brdfChoices(const CommandLine& cl);

} // namespace app
} // namespace shadelab

#endif
