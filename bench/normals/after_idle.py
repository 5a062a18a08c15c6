"""slPolyDataNormals updated after the thread pool had nothing to do, as in
a pipeline or an interactive program, on one thread and on all, beside
vtkTriangleMeshPointNormals (serial), in one process and one run.

Before each timed update the process sleeps --idle milliseconds, so the
pool's workers are asleep when the update starts and must be woken; or,
with --between vtkPolyDataNormals, runs vtkPolyDataNormals (no splitting,
serial) on the same mesh, as the normals bench's rounds do, which also
leaves other data in the caches and is the ratio's denominator there. On
kernels that wake a worker on the CPU of the thread that woke it (the
2-CPU KVM guests CI runs on), a worker found on the caller's CPU moves
itself off (shadelab/ThreadSpread.h); this bench shows what the second
thread gives then. A run times --updates updates of each job in turn; the
table has the median over runs of each run's median, and the range.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 bench/normals/after_idle.py \\
        [--triangles 0.1,0.5] [--idle 10] [--between sleep|vtkPolyDataNormals] [--updates 30] [--runs 5] [--threads N]
"""
import argparse
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import bench_common  # noqa: E402  (bench/common)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--triangles", default="0.1,0.5", help="millions of triangles, comma-separated (default %(default)s)")
    parser.add_argument("--idle", type=float, default=10, help="milliseconds of sleep before each update (default %(default)s)")
    parser.add_argument("--between", choices=("sleep", "vtkPolyDataNormals"), default="sleep",
                        help="what runs before each update: --idle ms of sleep (default) or vtkPolyDataNormals")
    parser.add_argument("--updates", type=int, default=30, help="timed updates of each job per run (default %(default)s)")
    bench_common.add_arguments(parser, runs=5)
    args = parser.parse_args()
    bench_common.apply_threads(args)
    bench_common.print_machine(args)

    import shadelab
    from vtkmodules.vtkCommonCore import vtkSMPTools
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals, vtkTriangleMeshPointNormals
    threads = args.threads if args.threads > 0 else os.cpu_count()

    def timed_update(f):
        """Seconds of one update of @p f, made to run again."""
        f.Modified()
        start = time.perf_counter()
        f.Update()
        return time.perf_counter() - start

    def normals(split):
        f = shadelab.slPolyDataNormals()
        f.SetSplitting(split)
        f.SetConsistency(split)
        return f

    # name: (make the filter, threads)
    jobs = {
        "angle, no split, 1 thread": (lambda: normals(False), 1),
        "angle, no split, %d threads" % threads: (lambda: normals(False), threads),
        "vtkTriangleMeshPointNormals": (vtkTriangleMeshPointNormals, 1),
        "split + consistency, 1 thread": (lambda: normals(True), 1),
        "split + consistency, %d threads" % threads: (lambda: normals(True), threads),
    }
    if args.between == "sleep":
        print("before each update: %g ms of sleep; %d updates a run; %d runs" % (args.idle, args.updates, args.runs))
    else:
        print("before each update: vtkPolyDataNormals (no splitting); %d updates a run; %d runs" % (
            args.updates, args.runs))
    for size in args.triangles.split(","):
        mesh = bench_common.sphere_with_normals(float(size) * 1e6)
        filters = {}
        for name, (make, _) in jobs.items():
            filters[name] = make()
            filters[name].SetInputData(mesh)
            filters[name].Update()
        if args.between == "vtkPolyDataNormals":
            before = vtkPolyDataNormals()
            before.SetInputData(mesh)
            before.SplittingOff()
            before.ConsistencyOff()
        medians = {name: [] for name in jobs}
        before_medians = []
        for _ in range(args.runs):
            before_times = []
            for name, (_, n) in jobs.items():
                vtkSMPTools.Initialize(n)
                times = []
                for _ in range(args.updates):
                    if args.between == "sleep":
                        time.sleep(args.idle / 1e3)
                    else:
                        before_times.append(timed_update(before))
                    times.append(timed_update(filters[name]))
                medians[name].append(statistics.median(times) * 1e3)
            if before_times:
                before_medians.append(statistics.median(before_times) * 1e3)
        print("\n== %s: %d triangles" % ("sphere", mesh.GetNumberOfCells()))
        print("   %-34s %9s %15s" % ("job", "median ms", "range ms"))
        for name, values in medians.items():
            print("   %-34s %9.2f %15s" % (name, statistics.median(values), "%.2f-%.2f" % (min(values), max(values))))

        def ratio(a, b):
            return statistics.median(x / y for x, y in zip(medians[a], medians[b]))
        print("   speed-up from 1 to %d threads: no split %.2f, split + consistency %.2f" % (
            threads, ratio("angle, no split, 1 thread", "angle, no split, %d threads" % threads),
            ratio("split + consistency, 1 thread", "split + consistency, %d threads" % threads)))
        print("   angle, no split, %d threads against vtkTriangleMeshPointNormals: %.2fx" % (
            threads, ratio("vtkTriangleMeshPointNormals", "angle, no split, %d threads" % threads)))
        if before_medians:
            # Each run's median vtkPolyDataNormals time over its median update.
            angle = medians["angle, no split, %d threads" % threads]
            print("   vtkPolyDataNormals (no splitting) %.2f ms; angle, no split, %d threads against it: %.2fx" % (
                statistics.median(before_medians), threads,
                statistics.median(b / a for b, a in zip(before_medians, angle))))


if __name__ == "__main__":
    main()
