// Ctrl-C, SIGTERM or SIGHUP while shadelab writes leaves no temporary file
// behind (shadelab::removeTemporaryFilesOnSignals(), AtomicFile.h). Installed
// by a static instance, as each subcommand registers itself (Commands.h):
// before main() runs, so before any output exists.
#include "shadelab/AtomicFile.h"

namespace
{
struct SignalCleanup
{
  SignalCleanup() { shadelab::removeTemporaryFilesOnSignals(); }
};
const SignalCleanup installed;
} // namespace
