#include "BenchArguments.h"

#include <vtkSMPTools.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <utility>

BenchArguments::BenchArguments(std::string program, std::string description, int defaultRuns)
  : Program(std::move(program))
  , Description(std::move(description))
  , Runs(defaultRuns)
{
  this->integer("runs", "runs of each measurement; the median is reported (default " +
      std::to_string(defaultRuns) + ")",
    &this->Runs, 1, 1000);
  const long long cores = std::max(1u, std::thread::hardware_concurrency());
  this->integer("threads", "threads for vtkSMPTools (default: all " + std::to_string(cores) + " cores)",
    &this->Threads, 1, 1024);
}

void BenchArguments::integer(
  const std::string& name, const std::string& help, long long* value, long long minimum, long long maximum)
{
  this->Options.push_back({ name, help,
    [=](const char* text) -> std::string {
      char* end = nullptr;
      errno = 0;
      const long long v = std::strtoll(text, &end, 10);
      if (errno || end == text || *end || v < minimum || v > maximum)
      {
        return "'" + std::string(text) + "' is not a whole number from " + std::to_string(minimum) + " to " +
          std::to_string(maximum);
      }
      *value = v;
      return "";
    },
    true, "N" });
}

void BenchArguments::text(const std::string& name, const std::string& metavar, const std::string& help,
  std::function<std::string(const std::string&)> set)
{
  this->Options.push_back({ name, help, [set](const char* value) { return set(value); }, true, metavar });
}

void BenchArguments::flag(const std::string& name, const std::string& help, bool* value)
{
  this->Options.push_back({ name, help,
    [=](const char*) -> std::string {
      *value = true;
      return "";
    },
    false, "" });
}

void BenchArguments::usage() const
{
  std::printf("usage: %s [options]\n%s\n\noptions:\n  %-22s %s\n", this->Program.c_str(),
    this->Description.c_str(), "--help", "this text");
  for (const Option& o : this->Options)
  {
    const std::string spelled = "--" + o.name + (o.takesValue ? " " + o.metavar : "");
    std::printf("  %-22s %s\n", spelled.c_str(), o.help.c_str());
  }
}

bool BenchArguments::parse(int argc, char** argv)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      this->usage();
      this->ExitCode = 0;
      return false;
    }
    const Option* found = nullptr;
    for (const Option& o : this->Options)
    {
      found = arg == "--" + o.name ? &o : found;
    }
    std::string problem;
    if (!found)
    {
      problem = "unknown option (--help lists them)";
    }
    else if (found->takesValue && i + 1 >= argc)
    {
      problem = "needs a value";
    }
    else
    {
      problem = found->set(found->takesValue ? argv[++i] : nullptr);
    }
    if (!problem.empty())
    {
      std::fprintf(stderr, "%s: %s: %s\n", this->Program.c_str(), arg.c_str(), problem.c_str());
      this->ExitCode = 2;
      return false;
    }
  }
  if (this->Threads > 0)
  {
    vtkSMPTools::Initialize(static_cast<int>(this->Threads));
  }
  return true;
}
