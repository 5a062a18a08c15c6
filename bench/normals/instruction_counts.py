"""Instructions per triangle of the normals filters, counted by valgrind's
callgrind, side by side in one run. Unlike a time, the count does not move
with the machine's load or speed (valgrind runs the same binary on the same
input to the same total), so it shows a change of a few percent that a
noisy machine hides from the timed bench (shadelab_bench_normals). It does
not see memory traffic: a pass that only reads costs few instructions and
much time, so read it beside the timed bench, not instead of it.

Each filter runs in a process of its own under callgrind, on the benches'
test sphere (bench/common), counting only inside its RequestData; the total
is divided by the triangles and the updates.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 bench/normals/instruction_counts.py \\
        [--triangles 0.2] [--runs 3] [--threads 1]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import bench_common  # noqa: E402  (bench/common)

# name: (class, module, settings, the peer its ratio is taken to)
JOBS = {
    "slPolyDataNormals angle, no split": ("slPolyDataNormals", "shadelab", "plain", "vtkTriangleMeshPointNormals"),
    "slPolyDataNormals area, no split": ("slPolyDataNormals", "shadelab", "plain area", "vtkTriangleMeshPointNormals"),
    "vtkTriangleMeshPointNormals": ("vtkTriangleMeshPointNormals", "vtkmodules.vtkFiltersCore", "",
                                    "vtkTriangleMeshPointNormals"),
    "vtkPolyDataNormals (split/cons off)": ("vtkPolyDataNormals", "vtkmodules.vtkFiltersCore", "plain",
                                           "vtkTriangleMeshPointNormals"),
    "slPolyDataNormals (defaults)": ("slPolyDataNormals", "shadelab", "", "vtkPolyDataNormals (defaults)"),
    "vtkPolyDataNormals (defaults)": ("vtkPolyDataNormals", "vtkmodules.vtkFiltersCore", "",
                                      "vtkPolyDataNormals (defaults)"),
}


def run_child(job, triangles, runs):
    """In the process under callgrind: updates @job's filter @runs times."""
    import importlib
    cls, module, settings, _ = JOBS[job]
    mesh = bench_common.sphere_with_normals(triangles)
    f = getattr(importlib.import_module(module), cls)()
    if "plain" in settings:
        f.SetSplitting(False)
        f.SetConsistency(False)
    if "area" in settings:
        f.SetWeighting(f.AREA)
    f.SetInputData(mesh)
    for _ in range(runs):
        f.Modified()
        f.Update()
    print(mesh.GetNumberOfCells())


def count(job, args):
    """Instructions callgrind collected in @job's RequestData, and the
    triangles of its mesh."""
    cls = JOBS[job][0]
    with tempfile.TemporaryDirectory() as folder:
        command = ["valgrind", "--tool=callgrind", "--callgrind-out-file=" + os.path.join(folder, "out"),
                   "--toggle-collect=%s::RequestData*" % cls, sys.executable, os.path.abspath(__file__),
                   "--child", job, "--triangles", str(args.triangles), "--runs", str(args.runs)]
        done = subprocess.run(command, check=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    collected = re.search(r"Collected : (\d+)", done.stderr)
    if not collected:
        sys.exit("instruction_counts: callgrind printed no count for %s:\n%s" % (job, done.stderr[-2000:]))
    return int(collected.group(1)), int(done.stdout.split()[-1])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--triangles", type=float, default=0.2, help="millions of triangles (default %(default)s)")
    bench_common.add_arguments(parser, runs=3)
    parser.add_argument("--child", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.runs < 1 or args.triangles <= 0:
        parser.error("--runs and --triangles must be positive")
    bench_common.apply_threads(args)
    if args.child:
        run_child(args.child, args.triangles * 1e6, args.runs)
        return
    bench_common.print_machine(args, args.threads)
    print("instructions per triangle inside each filter's RequestData (valgrind --tool=callgrind), "
          "%d updates of a sphere of about %gM triangles" % (args.runs, args.triangles), flush=True)
    per = {}
    for job in JOBS:
        total, triangles = count(job, args)
        per[job] = total / (triangles * args.runs)
    print("%-38s %14s %s" % ("filter", "instr/triangle", "x the peer's"))
    for job, (_, _, _, peer) in JOBS.items():
        ratio = "" if peer == job else "%.2f of %s" % (per[job] / per[peer], peer)
        print("%-38s %14.1f %s" % (job, per[job], ratio))


if __name__ == "__main__":
    main()
