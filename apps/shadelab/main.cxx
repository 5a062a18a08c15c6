// shadelab: the command-line tool, one subcommand per job.
#include "CommandLine.h"
#include "Commands.h"

#include "slOutputWindow.h"

#include "shadelab/OutOfMemory.h"

#include <exception>
#include <iostream>
#include <new>

#include <algorithm>

namespace shadelab
{
namespace app
{
namespace
{
std::vector<Command>& registry()
{
  static std::vector<Command> table;
  return table;
}
} // namespace

void reportProblem(const std::string& command, const std::string& message)
{
  std::cerr << "shadelab " << command << ": " << message << "\n";
}

CommandRegistration::CommandRegistration(const Command& command)
{
  std::vector<Command>& table = registry();
  table.insert(std::upper_bound(table.begin(), table.end(), command,
                 [](const Command& a, const Command& b) { return a.order < b.order; }),
    command);
}

const std::vector<Command>& commands()
{
  return registry();
}
} // namespace app
} // namespace shadelab

namespace
{
void printUsage(std::ostream& out)
{
  out << "usage: shadelab <subcommand> [options]   (shadelab <subcommand> --help for details)\n\n"
         "ShadeLab: local lighting (Lambert, Phong, Blinn-Phong) for VTK meshes.\n"
         "Any subcommand also takes --verbose: show VTK's and the image libraries' own warnings and errors.\n\nsubcommands:\n";
  for (const auto& command : shadelab::app::commands())
  {
    std::string name = command.name;
    name.resize(12, ' ');
    out << "  " << name << command.summary << "\n";
  }
}
} // namespace

int main(int argc, char** argv)
{
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h")
  {
    printUsage(args.empty() ? std::cerr : std::cout);
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "--version")
  {
    std::cout << "shadelab " << SHADELAB_VERSION << "\n";
    return 0;
  }
  // ShadeLab reports every problem itself, as one line that gives VTK's reason
  // (slErrorCapture); VTK's own multi-line reports (with source file names)
  // would only repeat it. --verbose shows them as well.
  const auto verbose = std::find(args.begin(), args.end(), "--verbose");
  const bool echo = verbose != args.end();
  if (echo)
  {
    args.erase(verbose);
  }
  slOutputWindow::Install(echo);

  const std::string name = args[0];
  for (const auto& command : shadelab::app::commands())
  {
    if (name == command.name)
    {
      try
      {
        return command.run(std::vector<std::string>(args.begin() + 1, args.end()));
      }
      catch (const shadelab::app::UsageError& e)
      {
        shadelab::app::reportProblem(name, e.what());
        return 2;
      }
      catch (const std::exception& e) // outside the work on a mesh (runOnMesh names it)
      {
        shadelab::app::reportProblem(name, shadelab::isOutOfMemory(e) ? "out of memory" : e.what());
        return 1;
      }
    }
  }
  std::cerr << "shadelab: unknown subcommand \"" << name << "\" (see shadelab --help)\n";
  return 2;
}
