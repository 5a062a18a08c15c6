#!/usr/bin/env bash
# The ParaView plugin's tests, inside a root with ParaView 5.11 and the
# plugin built in BUILD_DIR (scripts/paraview-test.sh does both):
#   1. the plugin loads in pvpython and every filter runs from paraview.simple;
#      the properties' defaults and ranges are the VTK classes', every
#      property has a tooltip, the diffuse colour array is chosen from a list,
#      state files and Python traces reproduce the pipeline;
#   2. pvbatch on 1, 2 and 3 MPI ranks (oversubscribed as needed), ParaView's
#      default ghost request off: normals, tangents and radiance agree with
#      the serial run at every point, and no ghost cells are left;
#   3. the ShadeLab Render View on 1 and 2 ranks and in ParaView's GUI
#      (under Xvfb): lit by the lighting pass;
#   4. the libexpat bug: expected to fail until Debian fixes it.
#
#   bash tests/paraview/run-tests.sh BUILD_DIR
set -euo pipefail
cd "$(dirname "$0")/../.."
build=$(realpath "$1")
plugin=$build/lib/paraview-5.11/plugins/ShadeLab/ShadeLab.so
here=tests/paraview
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# mpiexec as root, in a root whose name lookup may not know localhost.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi=(mpiexec --oversubscribe --host 127.0.0.1:3)

pvpython "$here/obj_to_vtp.py" data/meshes/spot.obj "$work/spot.vtp"
pvpython "$here/test_plugin.py" "$plugin" "$work/spot.vtp" data
# Under a display: the state file holds a ShadeLab Render View.
bash scripts/with-display.sh pvpython "$here/test_properties.py" "$plugin" "$work/spot.vtp" "$work"

for n in 1 2 3; do
  "${mpi[@]}" -n $n pvbatch --symmetric "$here/mpi_pieces.py" "$plugin" "$work/spot.vtp" "$work/ranks$n.pvtp"
done
pvpython "$here/compare_pieces.py" "$work/ranks1.pvtp" "$work/ranks2.pvtp" "$work/ranks3.pvtp"

bash scripts/with-display.sh pvpython "$here/test_view.py" "$plugin" "$work/spot.vtp" "$work"
bash scripts/with-display.sh "${mpi[@]}" -n 2 pvbatch --symmetric "$here/test_view.py" "$plugin" \
  "$work/spot.vtp" "$work"
bash "$here/test_gui_view.sh" "$plugin" "$work/spot.vtp" "$work"

if pvpython "$here/test_libexpat.py" "$work/spot.vtp" "$work"; then
  echo "test_libexpat.py passed: Debian's ParaView now reads appended XML; the expected failure can go" >&2
  exit 1
fi
echo "test_libexpat.py: failed as expected (Debian 12's ParaView 5.11 with its current libexpat)"
