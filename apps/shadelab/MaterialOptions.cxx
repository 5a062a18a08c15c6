#include "MaterialOptions.h"

#include "shadelab/Scene.h"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace shadelab
{
namespace app
{

std::string materialOptionName(const char* key)
{
  std::string name;
  for (const char* c = key; *c; ++c)
  {
    const auto ch = static_cast<unsigned char>(*c);
    if (std::isupper(ch))
    {
      name += '-';
    }
    name += static_cast<char>(std::tolower(ch));
  }
  return name;
}

std::vector<OptionSpec> withMaterialOptions(std::vector<OptionSpec> specs, const std::string& defaults)
{
  return withMaterialOptions(std::move(specs), [&](const MaterialParameterInfo&) { return defaults; });
}

std::vector<OptionSpec> withMaterialOptions(
  std::vector<OptionSpec> specs, const std::function<std::string(const MaterialParameterInfo&)>& defaultOf)
{
  std::vector<OptionSpec> numbers;
  for (const MaterialParameterInfo& row : kMaterialParameters)
  {
    if (!row.colour)
    {
      std::ostringstream help;
      help << row.meaning << "; in [" << row.lo << ", " << row.hi << "] (" << defaultOf(row) << ")";
      numbers.push_back({ materialOptionName(row.key), "", "X", help.str() });
    }
  }
  // Before --help, which --help lists last.
  auto help = std::find_if(specs.begin(), specs.end(), [](const OptionSpec& s) { return s.name == "help"; });
  specs.insert(help, numbers.begin(), numbers.end());
  return specs;
}

double materialNumber(const CommandLine& cl, const MaterialParameterInfo& row, double fallback)
{
  return cl.getNumber(materialOptionName(row.key), fallback, row.lo, row.hi);
}

namespace
{
void setFromOption(const CommandLine& cl, const MaterialParameterInfo& row, float& value)
{
  value = static_cast<float>(materialNumber(cl, row, static_cast<double>(value)));
}
// Colours are not options: k_d and k_s come from the scene (or, for a lone
// lobe, --kd and --ks).
void setFromOption(const CommandLine&, const MaterialParameterInfo&, glm::vec3&) {}
} // namespace

void applyMaterialOptions(const CommandLine& cl, SceneMaterial& material)
{
#define SHADELAB_ROW(type, field, ...) setFromOption(cl, materialRows::field, material.field);
  SHADELAB_MATERIAL_PARAMETERS(SHADELAB_ROW)
#undef SHADELAB_ROW
}

} // namespace app
} // namespace shadelab
