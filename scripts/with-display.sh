#!/usr/bin/env bash
# Runs a command with an X display: as is when DISPLAY is set, otherwise under
# xvfb-run (Debian's VTK renders through X11 only).
set -euo pipefail
if [ -n "${DISPLAY:-}" ]; then
  exec "$@"
fi
# -noreset: Xvfb otherwise resets whenever its last client leaves, and a
# connection racing with that reset fails ("bad X server connection").
exec xvfb-run -a -s "-screen 0 1280x1024x24 -nolisten tcp -noreset" "$@"
