#include "BrdfOptions.h"

namespace shadelab
{
namespace app
{

std::vector<OptionSpec> brdfOptionSpecs()
{
  return {
    { "brdf", "", "FILE", "a BRDF Explorer .brdf file (repeatable; docs/brdf-files.md)" },
    { "param", "", "NAME=VALUE", "a parameter of the --brdf file before it (repeatable; colour: R,G,B)" },
  };
}

std::vector<BrdfChoice> brdfChoices(const CommandLine& cl)
{
  std::vector<BrdfChoice> choices;
  for (const auto& [name, value] : cl.ordered())
  {
    if (name == "brdf")
    {
      choices.push_back({ value, {} });
    }
    else if (name == "param")
    {
      if (choices.empty())
      {
        throw UsageError("--param " + value + " comes before any --brdf FILE");
      }
      choices.back().overrides.push_back(value);
    }
  }
  return choices;
}

} // namespace app
} // namespace shadelab
