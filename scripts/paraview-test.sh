#!/usr/bin/env bash
# The ParaView plugin: install ParaView 5.11 and what its CMake config needs,
# build plugins/ParaView in ./build-pv, run tests/paraview/run-tests.sh.
# Run it only where ParaView may be installed: python3-paraview conflicts
# with python3-vtk9, which the main build needs (docs/paraview.md). CI runs
# it in a clean Debian 12 root (scripts/paraview-ci.sh).
#
#   bash scripts/paraview-test.sh [--build-only]
set -euo pipefail
cd "$(dirname "$0")/.."
build_only=${1:-}

packages=(
  paraview paraview-dev python3-paraview  # ParaView 5.11 with its own VTK 9.2
  mpi-default-bin mpi-default-dev          # Open MPI: mpiexec, and MPI::MPI_C for ParaView's config
  # needed by paraview-dev's CMake config but not among its dependencies:
  libdouble-conversion-dev liblzma-dev liblz4-dev libutfcpp-dev
  cmake g++ make libglm-dev nlohmann-json3-dev  # ShadeLab's build and lighting core
  libopenimageio-dev openimageio-tools          # images (OIIO's CMake config names its tools)
  libx11-dev libxt-dev libgl-dev libglew-dev libfreetype-dev  # the render view: ParaView's rendering modules' config
  xvfb xauth                                    # the render view's tests draw offscreen through X11
)
bash scripts/install-deps.sh --only "${packages[@]}"

cmake -S plugins/ParaView -B build-pv -DCMAKE_BUILD_TYPE=Release -DSHADELAB_WERROR=ON --log-level=WARNING
cmake --build build-pv -j2
if [ "$build_only" != --build-only ]; then
  bash tests/paraview/run-tests.sh build-pv
fi
