#ifndef shadelab_app_MaterialOptions_h
#define shadelab_app_MaterialOptions_h
/**
 * @file MaterialOptions.h
 * @brief The command line's material numbers: one option per number row of
 * the material table (shadelab/LightingTables.h), named after the row's
 * scene key (roughnessX -> --roughness-x), with the row's meaning and range
 * as its help and its check. A new row is a new option of every
 * subcommand that takes them.
 */

#include "CommandLine.h"

#include "shadelab/MaterialParameters.h"

#include <functional>
#include <string>
#include <vector>

namespace shadelab
{
struct SceneMaterial;

namespace app
{

/// The option of material parameter @p key: "roughnessX" -> "roughness-x".
std::string materialOptionName(const char* key);

/// @p specs with one option per number row of the material table, before
/// --help; @p defaults ends each help line ("default: the scene's").
std::vector<OptionSpec> withMaterialOptions(std::vector<OptionSpec> specs, const std::string& defaults);

/// As above, with @p defaultOf(row) ending the help line of each row, for
/// a command whose defaults differ from row to row.
std::vector<OptionSpec> withMaterialOptions(
  std::vector<OptionSpec> specs, const std::function<std::string(const MaterialParameterInfo&)>& defaultOf);

/// The value of @p row's option, or @p fallback if it was not given. Throws
/// UsageError naming the option for a value that is not a number in the
/// row's range.
double materialNumber(const CommandLine& cl, const MaterialParameterInfo& row, double fallback);

/// Every material number given on @p cl onto @p material (the others are
/// left as they are). Throws UsageError as materialNumber() does.
void applyMaterialOptions(const CommandLine& cl, SceneMaterial& material);

/// Every material number given on @p cl onto @p target, a filter that takes
/// them by key (SetMaterialParameter(): slBRDFLobeSource, slAlbedoTable);
/// the others keep the filter's defaults. Throws UsageError as
/// materialNumber() does.
template <typename Target>
void applyMaterialOptionsByKey(const CommandLine& cl, Target* target)
{
  for (const MaterialParameterInfo& row : kMaterialParameters)
  {
    if (!row.colour && cl.has(materialOptionName(row.key)))
    {
      target->SetMaterialParameter(row.key, materialNumber(cl, row, row.number));
    }
  }
}

} // namespace app
} // namespace shadelab

#endif
