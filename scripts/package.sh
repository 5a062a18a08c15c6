#!/usr/bin/env bash
# Builds the Debian packages (shadelab, shadelab-dev, python3-shadelab) from
# ./build with CPack, into the folder given (default: build/packages).
#
#   bash scripts/package.sh [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(realpath -m "${1:-build/packages}")
# dpkg-shlibdeps (dpkg-dev) reads the library dependencies off the binaries.
bash scripts/install-deps.sh --only dpkg-dev file
if [ ! -f build/CMakeCache.txt ]; then
  bash scripts/build.sh
fi
mkdir -p "$out"
(cd build && cpack -G DEB -B "$out/cpack" > "$out/cpack.log") || { cat "$out/cpack.log" >&2; exit 1; }
mv "$out"/cpack/*.deb "$out"/
rm -rf "$out/cpack"
for deb in "$out"/*.deb; do
  echo "package: $(basename "$deb") ($(du -k "$deb" | cut -f1) KiB): $(dpkg-deb -f "$deb" Depends)"
done
