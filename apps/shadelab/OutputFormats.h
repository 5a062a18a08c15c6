#ifndef shadelab_app_OutputFormats_h
#define shadelab_app_OutputFormats_h
/**
 * @file OutputFormats.h
 * @brief The one table of what each kind of output file may be called, used
 * by every subcommand's check of its output names and by the help text.
 *
 * The mesh and image extensions are those slMeshWriter and slImageWriter
 * write; a table is CSV. An output whose extension does not fit what the
 * subcommand writes there is a UsageError before any work is done (a
 * `t.png` that would hold CSV, an image without an extension).
 */
#include <initializer_list>
#include <string>

namespace shadelab
{
namespace app
{
class CommandLine;

enum class OutputKind
{
  Mesh,
  Image,
  Table,
};

/// "mesh", "image" or "table".
const char* outputKindName(OutputKind kind);

/// The extensions files of @p kind may have, space separated (".vtp .vtk ...").
const char* outputExtensions(OutputKind kind);

/// Which of @p allowed the file @p path is, by its extension. Throws
/// UsageError "PATH: unsupported mesh format ".png" (supported: .vtp ...)"
/// or, with several kinds allowed, "PATH: unsupported output format ".xyz"
/// (mesh: .vtp ...; image: .png ...)".
OutputKind checkOutputName(const std::string& path, std::initializer_list<OutputKind> allowed);

/// checkOutputName() for option @p option of @p cl, if given.
void checkOutputOption(const CommandLine& cl, const std::string& option, std::initializer_list<OutputKind> allowed);

/// "@p what (.vtp .vtk ...)" for an option's help line.
std::string outputHelp(const std::string& what, OutputKind kind);

} // namespace app
} // namespace shadelab

#endif
