#!/usr/bin/env bash
# The ShadeLab Render View drawn by ParaView's GUI: the `paraview` client
# loads the plugin at startup (PV_PLUGIN_PATH) and runs test_view.py as its
# startup script, under Xvfb; the script's checks create the view in the
# GUI's layout and read back what its render widget drew.
#
#   bash tests/paraview/test_gui_view.sh PLUGIN MESH.vtp WORK_DIR
set -euo pipefail
cd "$(dirname "$0")/../.."
plugin=$(realpath "$1") mesh=$(realpath "$2") work=$(realpath "$3")
rm -f "$work/gui-result.txt"
# The GUI keeps its settings under HOME: a fresh one, so no earlier
# session's settings (or a missing HOME in a bare root) change the run.
home=$(mktemp -d)
trap 'rm -rf "$home"' EXIT
status=0
HOME=$home PV_PLUGIN_PATH=$(dirname "$plugin") SHADELAB_VIEW_TEST="$plugin $mesh $work" \
  timeout 300 bash scripts/with-display.sh paraview --dr --script="$PWD/tests/paraview/test_view.py" \
  > "$work/gui.log" 2>&1 || status=$?
if [ ! -s "$work/gui-result.txt" ]; then
  tail -40 "$work/gui.log" >&2
  echo "test_gui_view: the GUI ended (status $status) without running the view's checks" >&2
  exit 1
fi
result=$(cat "$work/gui-result.txt")
if [ "$result" != ok ]; then
  echo "test_gui_view: $result" >&2
  exit 1
fi
grep -E "emission-only scene|flat against phong" "$work/gui.log" || true
echo "test_gui_view: the GUI's ShadeLab Render View is lit by the lighting pass"
