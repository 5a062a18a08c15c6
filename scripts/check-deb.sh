#!/usr/bin/env bash
# Installs ShadeLab's Debian packages from a folder on a machine that does not
# have them (a clean root, in CI) and uses them as a user would: shadelab
# render offscreen, import shadelab from Debian's python3, and a downstream
# CMake project against shadelab-dev. Only apt's dependency resolution brings
# in what the packages declare.
#
#   bash scripts/check-deb.sh DEB_DIR
set -euo pipefail
cd "$(dirname "$0")/.."
debs=$(realpath "${1:?usage: check-deb.sh DEB_DIR}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
# The packages, plus what this check itself uses: an X server for rendering
# and a compiler for the downstream project.
apt-get install -y -qq --no-install-recommends \
  "$debs"/shadelab_*.deb "$debs"/shadelab-dev_*.deb "$debs"/python3-shadelab_*.deb \
  xvfb xauth cmake g++ make > "$work/apt.log" || { tail -n 30 "$work/apt.log" >&2; exit 1; }

echo "check-deb: installed $(dpkg-query -W -f='${Package} ${Version}, ' shadelab shadelab-dev python3-shadelab)"

xvfb-run -a -s "-screen 0 1280x1024x24 -nolisten tcp" \
  shadelab render /usr/share/shadelab/meshes/spot.obj --scene /usr/share/shadelab/scenes/default.json \
  --size 160x120 -o "$work/spot.png"
python3 - "$work/spot.png" <<'PY'
import sys
with open(sys.argv[1], "rb") as f:
    head = f.read(24)
assert head[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
width, height = int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
assert (width, height) == (160, 120), (width, height)
print(f"check-deb: shadelab render wrote a {width}x{height} PNG")
PY

/usr/bin/python3 -c "
import shadelab
assert shadelab.__file__ == '/usr/lib/python3/dist-packages/shadelab/__init__.py', shadelab.__file__
scene = shadelab.slScene()
assert scene.ReadFile('/usr/share/shadelab/scenes/default.json')
print('check-deb: import shadelab from', shadelab.__file__, 'with', scene.GetNumberOfLights(), 'lights')"

cmake -S tests/install/downstream -B "$work/downstream" -DCMAKE_BUILD_TYPE=Release > "$work/cmake.log" \
  || { cat "$work/cmake.log" >&2; exit 1; }
cmake --build "$work/downstream" > "$work/build.log" || { cat "$work/build.log" >&2; exit 1; }
"$work/downstream/downstream"
echo "check-deb: all checks passed"
