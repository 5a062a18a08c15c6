#!/usr/bin/env bash
# Strong scaling of the ParaView plugin (docs/paraview.md, Scale): builds it
# (scripts/paraview-test.sh --build-only), then runs tests/paraview/scale.py
# (each rank generates its piece of a sphere; ShadeLab Normals, then ShadeLab
# Radiance) on 1, 2 and 4 MPI ranks, RUNS times each, interleaved so that a
# change in the machine's load touches every rank count alike. Prints one
# line per run and the median and range per rank count. Run it where
# ParaView may be installed:
#
#   bash scripts/clean-root.sh --name paraview "bash scripts/paraview-scale.sh [RESOLUTION [RUNS [THREADS]]]"
#
# RESOLUTION 2050 (default) gives 8,396,800 triangles; RUNS defaults to 5;
# THREADS, the vtkSMPTools threads per rank, to VTK's choice (every core).
set -euo pipefail
cd "$(dirname "$0")/.."
resolution=${1:-2050}
runs=${2:-5}
threads=${3:-0}
bash scripts/paraview-test.sh --build-only
plugin=$PWD/build-pv/lib/paraview-5.11/plugins/ShadeLab/ShadeLab.so
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
log=$(mktemp)
trap 'rm -f "$log"' EXIT
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores;" \
  "$(awk '/MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo)"
for run in $(seq "$runs"); do
  for n in 1 2 4; do
    echo "run $run, $n ranks (load average $(cut -d' ' -f1-3 /proc/loadavg))"
    mpiexec --oversubscribe --host 127.0.0.1:4 -n "$n" pvbatch --symmetric tests/paraview/scale.py "$plugin" \
      "$resolution" "$threads" | tee -a "$log"
  done
done
/usr/bin/python3 tests/paraview/scale_summary.py < "$log"
