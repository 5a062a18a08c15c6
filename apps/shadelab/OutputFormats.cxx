#include "OutputFormats.h"

#include "CommandLine.h"
#include "slFileExtension.h"
#include "slImageWriter.h"
#include "slMeshWriter.h"

namespace shadelab
{
namespace app
{

const char* outputKindName(OutputKind kind)
{
  switch (kind)
  {
    case OutputKind::Mesh:
      return "mesh";
    case OutputKind::Image:
      return "image";
    case OutputKind::Table:
      return "table";
  }
  return "";
}

const char* outputExtensions(OutputKind kind)
{
  switch (kind)
  {
    case OutputKind::Mesh:
      return slMeshWriter::GetSupportedExtensions();
    case OutputKind::Image:
      return slImageWriter::GetSupportedExtensions();
    case OutputKind::Table:
      return ".csv";
  }
  return "";
}

OutputKind checkOutputName(const std::string& path, std::initializer_list<OutputKind> allowed)
{
  const std::string ext = slLowerExtension(path.c_str());
  for (OutputKind kind : allowed)
  {
    if (slExtensionInList(ext, outputExtensions(kind)))
    {
      return kind;
    }
  }
  if (allowed.size() == 1)
  {
    const OutputKind kind = *allowed.begin();
    throw UsageError(path + ": " + slFormatProblem(path.c_str(), outputKindName(kind), outputExtensions(kind)));
  }
  std::string supported;
  for (OutputKind kind : allowed)
  {
    supported += std::string(supported.empty() ? "" : "; ") + outputKindName(kind) + ": " +
      outputExtensions(kind);
  }
  const std::string problem =
    ext.empty() ? "no file extension to tell the output format" : "unsupported output format \"" + ext + "\"";
  throw UsageError(path + ": " + problem + " (" + supported + ")");
}

void checkOutputOption(const CommandLine& cl, const std::string& option, std::initializer_list<OutputKind> allowed)
{
  if (cl.has(option))
  {
    checkOutputName(cl.get(option), allowed);
  }
}

std::string outputHelp(const std::string& what, OutputKind kind)
{
  return what + " (" + outputExtensions(kind) + ")";
}

} // namespace app
} // namespace shadelab
