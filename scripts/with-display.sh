#!/usr/bin/env bash
# Runs a command with an X display: as is when DISPLAY is set, otherwise under
# xvfb-run (Debian's VTK renders through X11 only).
set -euo pipefail
if [ -n "${DISPLAY:-}" ]; then
  exec "$@"
fi
# A free display number: xvfb-run -a checks only the lock files in this
# root's /tmp, but an X server in another root on this machine (a clean-root
# run, or the host beside one) shows only as its abstract socket, which
# clients try first: "bad X server connection". Skip those numbers too.
n=99
while [ -e "/tmp/.X$n-lock" ] || grep -q "@/tmp/.X11-unix/X$n\$" /proc/net/unix 2>/dev/null; do
  n=$((n + 1))
done
# -noreset: Xvfb otherwise resets whenever its last client leaves, and a
# connection racing with that reset fails ("bad X server connection").
exec xvfb-run -n "$n" -s "-screen 0 1280x1024x24 -nolisten tcp -noreset" "$@"
