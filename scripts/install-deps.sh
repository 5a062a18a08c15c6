#!/usr/bin/env bash
# Installs exactly the Debian 12 packages ShadeLab needs. Idempotent: runs
# apt-get update and install only when something is missing.
#
#   bash scripts/install-deps.sh [EXTRA_PACKAGE ...]
#   bash scripts/install-deps.sh --only PACKAGE ...
#
# With no argument: what the README's two commands need (build, tests, demo).
# CI steps that need more (a sanitizer or fuzzing compiler, ...) name their
# extra packages as arguments, or --only the packages they need, so there is
# one place that checks and installs.
set -euo pipefail

if [ "${1:-}" = "--only" ]; then
  shift
  packages=("$@")
else
  packages=(
    cmake g++ make                    # build
    libvtk9-dev python3-vtk9 python3-dev  # VTK 9.1 C++ and Python (wrapping tools come with python3-vtk9)
    libglm-dev                        # lighting core
    nlohmann-json3-dev                # scene files
    libopenimageio-dev openimageio-tools  # every image read and written (OIIO's CMake config names its tools)
    libopenmesh-dev                   # half-edge meshes
    libgtest-dev                      # tests
    xvfb xauth                        # offscreen rendering: Debian's VTK is X11-only
    glslang-tools                     # checks that the lighting core is valid GLSL
    python3-numpy                     # the numpy peer in the lighting benchmark
    qtbase5-dev libvtk9-qt-dev        # shadelab-viewer (Qt 5, QVTKOpenGLNativeWidget, QtTest)
    "$@"
  )
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing packages: ${missing[*]} (run as root, or install them)" >&2
  exit 1
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" > /dev/null
