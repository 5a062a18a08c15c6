#!/usr/bin/env bash
# CI for the ParaView plugin: scripts/paraview-test.sh in a clean Debian 12
# root of its own (ParaView cannot share a system with the main build).
# About 10 minutes on 2 idle cores: installing ParaView, 1.5 minutes of
# build, 1 minute of tests.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/clean-root.sh --name paraview "bash scripts/paraview-test.sh"
