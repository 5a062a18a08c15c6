#ifndef shadelab_app_Commands_h
#define shadelab_app_Commands_h
/**
 * @file Commands.h
 * @brief The table of `shadelab` subcommands.
 */

#include <string>
#include <vector>

namespace shadelab
{
namespace app
{

struct Command
{
  int order; ///< position in `shadelab --help`
  const char* name;
  const char* summary;
  /// Runs with the arguments after the subcommand name; returns the exit
  /// status or throws UsageError / shadelab::Error.
  int (*run)(const std::vector<std::string>& args);
};

/// Prints "shadelab COMMAND: MESSAGE" on stderr: every problem, one line.
void reportProblem(const std::string& command, const std::string& message);

/// Every registered subcommand, in the order `shadelab --help` lists them.
const std::vector<Command>& commands();

/// Each subcommand's file registers itself with a static instance:
/// `static const CommandRegistration registration{ { 10, "render", "...", &run } };`
struct CommandRegistration
{
  explicit CommandRegistration(const Command& command);
};

} // namespace app
} // namespace shadelab

#endif
