#!/usr/bin/env bash
# Build, then run the whole test suite with ctest (rendering tests under Xvfb).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd build
bash ../scripts/with-display.sh ctest --output-on-failure --parallel "$(nproc)" "$@"
