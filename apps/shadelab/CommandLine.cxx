#include "CommandLine.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace shadelab
{
namespace app
{

CommandLine::CommandLine(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs)
{
  auto find = [&](const std::string& word) -> const OptionSpec* {
    for (const OptionSpec& spec : specs)
    {
      if (word == "--" + spec.name || (!spec.shortName.empty() && word == "-" + spec.shortName))
      {
        return &spec;
      }
    }
    return nullptr;
  };
  for (size_t i = 0; i < args.size(); ++i)
  {
    std::string word = args[i];
    std::string inlineValue;
    bool hasInlineValue = false;
    const size_t equals = word.find('=');
    if (word.rfind("--", 0) == 0 && equals != std::string::npos)
    {
      inlineValue = word.substr(equals + 1);
      word = word.substr(0, equals);
      hasInlineValue = true;
    }
    if (word.size() < 2 || word[0] != '-')
    {
      this->Positional.push_back(word);
      continue;
    }
    const OptionSpec* spec = find(word);
    if (!spec)
    {
      throw UsageError("unknown option " + word + " (see --help)");
    }
    if (spec->valueName.empty())
    {
      if (hasInlineValue)
      {
        throw UsageError("option --" + spec->name + " takes no value");
      }
      this->Values[spec->name] = "1";
      this->Ordered.emplace_back(spec->name, "1");
      continue;
    }
    if (!hasInlineValue)
    {
      if (i + 1 >= args.size())
      {
        throw UsageError("option " + word + " needs a value (" + spec->valueName + ")");
      }
      inlineValue = args[++i];
    }
    if (!spec->choices.empty() &&
      std::find(spec->choices.begin(), spec->choices.end(), inlineValue) == spec->choices.end())
    {
      std::string names;
      for (const std::string& choice : spec->choices)
      {
        names += (names.empty() ? "" : ", ") + choice;
      }
      throw UsageError("--" + spec->name + ": unknown value \"" + inlineValue + "\" (" + names + ")");
    }
    this->Values[spec->name] = inlineValue;
    this->Ordered.emplace_back(spec->name, inlineValue);
  }
}

std::string CommandLine::get(const std::string& name, const std::string& fallback) const
{
  auto it = this->Values.find(name);
  return it == this->Values.end() ? fallback : it->second;
}

double CommandLine::getNumber(const std::string& name, double fallback, double lo, double hi) const
{
  auto it = this->Values.find(name);
  if (it == this->Values.end())
  {
    return fallback;
  }
  char* end = nullptr;
  const double value = std::strtod(it->second.c_str(), &end);
  if (it->second.empty() || *end != '\0' || !std::isfinite(value))
  {
    throw UsageError("--" + name + ": \"" + it->second + "\" is not a number");
  }
  if (value < lo || value > hi)
  {
    std::ostringstream s;
    s << "--" << name << ": " << value << " is out of range [" << lo << ", " << hi << "]";
    throw UsageError(s.str());
  }
  return value;
}

int CommandLine::getIndex(const std::string& name, int fallback, int lo, int hi) const
{
  const double value = this->getNumber(name, fallback, lo, hi);
  if (value != std::floor(value))
  {
    throw UsageError("--" + name + ": \"" + this->get(name) + "\" is not a whole number");
  }
  return static_cast<int>(value);
}

const std::string& CommandLine::meshWithOutput() const
{
  if (this->Positional.size() != 1)
  {
    throw UsageError("expected one MESH argument, got " + std::to_string(this->Positional.size()));
  }
  if (!this->has("output"))
  {
    throw UsageError("missing -o/--output FILE");
  }
  return this->Positional[0];
}

bool CommandLine::printHelpIfAsked(
  const std::string& usage, const std::string& description, const std::vector<OptionSpec>& specs) const
{
  if (!this->has("help"))
  {
    return false;
  }
  std::cout << "usage: " << usage << "\n\n" << description << "\n\noptions:\n" << describe(specs);
  return true;
}

std::string CommandLine::describe(const std::vector<OptionSpec>& specs)
{
  std::ostringstream out;
  for (const OptionSpec& spec : specs)
  {
    std::string left = "  " + (spec.shortName.empty() ? std::string("    ") : "-" + spec.shortName + ", ") + "--" +
      spec.name + (spec.valueName.empty() ? "" : " " + spec.valueName);
    left.resize(std::max<size_t>(left.size() + 2, 30), ' ');
    out << left << spec.help << "\n";
  }
  return out.str();
}

} // namespace app
} // namespace shadelab
