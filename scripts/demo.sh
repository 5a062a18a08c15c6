#!/usr/bin/env bash
# The main job: build, then render the bundled default scene offscreen.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out
bash scripts/with-display.sh build/bin/shadelab render data/meshes/spot.obj \
  --scene data/scenes/default.json -o out/default.png
bash docs/make-images.sh out/gallery
echo "ShadeLab demo images are in $(pwd)/out/ (the default scene: out/default.png; the gallery: out/gallery/)"
