#!/usr/bin/env bash
# Regenerates the pictures in docs/images (or in the folder given) with
# ShadeLab's own commands; scripts/demo.sh runs it into out/gallery.
#   bash docs/make-images.sh [FOLDER]        (after scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
shadelab=build/bin/shadelab
run() { bash scripts/with-display.sh "$shadelab" "$@" > /dev/null; }
spot=data/meshes/spot.obj
scene=data/scenes/default.json
out=${1:-docs/images}
mkdir -p "$out"

run render "$spot" --scene "$scene" -o "$out/default-scene.png"
for frequency in flat gouraud phong; do
  run render "$spot" --scene "$scene" --frequency "$frequency" --size 400x300 -o "$out/pass-frequency-$frequency.png"
done
for model in lambert phong blinn-phong; do
  run render "$spot" --scene "$scene" --model "$model" --size 400x300 -o "$out/pass-model-$model.png"
done
for component in ambient diffuse specular emission; do
  run render "$spot" --scene "$scene" --component "$component" --size 400x300 -o "$out/pass-component-$component.png"
done
run render "$spot" --scene "$scene" --component cos --light 0 --false-color --size 400x300 -o "$out/pass-component-cos.png"
run render "$spot" --scene "$scene" --vtk-lighting --quiet --size 400x300 -o "$out/pass-vtk-builtin.png"
echo "images written to $out/"
# Field images: the terms of the lighting equation and the Monte Carlo reference.
tmp=$(mktemp -d)
run light "$spot" --scene "$scene" -o "$tmp/light.vtp" --image "$out/fields-light.png"
run reference "$spot" --scene "$scene" -o "$tmp/reference.vtp" --image "$out/fields-reference.png"
run compare "$spot" --scene "$scene" --diff --size 300x225 -o "$out/compare-frequencies.png"
run lobe "$spot" --scene "$scene" --points 24 --scale 0.12 -o "$out/lobes-on-spot.png"
run lobe --models phong,blinn-phong,phong-normalized,blinn-phong-normalized --incidence 50 -o "$out/lobes-four-models.png"
run lobe --models phong-normalized --shininess 50 --brdf data/brdf/blinn-phong-normalized.brdf --param kd=0 --param ks=1 \
  --brdf data/brdf/ward-anisotropic.brdf --incidence 40 -o "$out/lobes-brdf-files.png"
run render "$spot" --scene data/scenes/glow.json -o "$out/tutorial-glow.png"
run render "$spot" --scene data/scenes/glow.json --component emission -o "$out/tutorial-glow-emission.png"
rm -rf "$tmp"
echo "field and comparison images written to $out/"
# The Qt viewer: its whole window, panels included (light widgets show in the view).
viewer() { bash scripts/with-display.sh build/bin/shadelab-viewer "$@" > /dev/null 2>&1; }
viewer "$spot" --scene "$scene" --panel Lights --window-screenshot "$out/viewer-lights.png"
viewer "$spot" --scene "$scene" --panel Material --split --window-screenshot "$out/viewer-split.png"
echo "viewer pictures written to $out/"
