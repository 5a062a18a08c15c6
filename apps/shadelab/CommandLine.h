#ifndef shadelab_app_CommandLine_h
#define shadelab_app_CommandLine_h
/**
 * @file CommandLine.h
 * @brief The small option parser shared by every `shadelab` subcommand.
 *
 * Options are `--name value` or `--name=value`, short aliases like `-o`, and
 * positional arguments. Every problem is a UsageError whose text is one line.
 */

#include "shadelab/Error.h"

#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace shadelab
{
namespace app
{

/// Bad command-line use: exit status 2, message printed as one line.
struct UsageError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// Bad input or a failed job is a shadelab::Error (shadelab/Error.h): exit
// status 1, its one-line message printed.

/// One option a subcommand accepts.
struct OptionSpec
{
  std::string name;      ///< long name without dashes, e.g. "scene"
  std::string shortName; ///< e.g. "o", or ""
  std::string valueName; ///< e.g. "FILE"; empty for a flag
  std::string help;
  /// The values the option may take; empty: any. Checked when parsing.
  std::vector<std::string> choices = {};
};

class CommandLine
{
public:
  /// Parses @p args (without the program and subcommand names). Throws UsageError.
  CommandLine(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs);

  bool has(const std::string& name) const { return this->Values.count(name) != 0; }
  std::string get(const std::string& name, const std::string& fallback = std::string()) const;
  /// A number option in [lo, hi]; throws UsageError naming the option otherwise.
  double getNumber(const std::string& name, double fallback, double lo, double hi) const;
  /// A whole-number option (an index) in [lo, hi]; throws UsageError naming
  /// the option otherwise ("0.5" is not taken as 0).
  int getIndex(const std::string& name, int fallback, int lo, int hi) const;
  const std::vector<std::string>& positional() const { return this->Positional; }
  /// Every option given, in command-line order, as (name, value): a repeated
  /// option appears each time (get() gives its last value); a flag's value is "1".
  const std::vector<std::pair<std::string, std::string>>& ordered() const { return this->Ordered; }

  /// The single MESH argument of a job that also needs -o/--output. Throws
  /// UsageError ("expected one MESH argument, got N", "missing -o/--output FILE").
  const std::string& meshWithOutput() const;

  /// Prints "usage: USAGE", @p description and the options to stdout if
  /// --help was given; returns whether it did.
  bool printHelpIfAsked(const std::string& usage, const std::string& description,
    const std::vector<OptionSpec>& specs) const;

  /// "  -o, --output FILE   help" lines for --help.
  static std::string describe(const std::vector<OptionSpec>& specs);

private:
  std::map<std::string, std::string> Values;
  std::vector<std::string> Positional;
  std::vector<std::pair<std::string, std::string>> Ordered;
};

} // namespace app
} // namespace shadelab

#endif
