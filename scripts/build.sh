#!/usr/bin/env bash
# Configures and builds ShadeLab in ./build (Release, all cores, warnings are errors).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSHADELAB_WERROR=ON --log-level=WARNING
cmake --build build --parallel "$(nproc)"
