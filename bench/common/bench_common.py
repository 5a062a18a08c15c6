"""What the Python benches share: the machine they run on, printed by
shadelab_bench_machine (bench/common/BenchMachine: CPU model, cores,
threads, memory, load, and the memory bandwidth measured now); the
--threads option of the CPU benches, which reaches vtkSMPTools in this
process and in every program run from it through VTK_SMP_MAX_THREADS; and
the test mesh, a sphere with point normals."""
import os
import subprocess


def add_machine_argument(parser):
    """--machine: the program that describes the machine."""
    parser.add_argument("--machine", default="build/bin/shadelab_bench_machine",
                        help="the program that describes the machine (default %(default)s)")


def add_arguments(parser, runs):
    """--runs, --threads and --machine, as every ShadeLab CPU bench takes them."""
    parser.add_argument("--runs", type=int, default=runs,
                        help="runs of each measurement; the median and range are reported (default %d)" % runs)
    parser.add_argument("--threads", type=int, default=0,
                        help="threads for vtkSMPTools (default: all %d cores)" % os.cpu_count())
    add_machine_argument(parser)


def apply_threads(args):
    """Sets the thread count for vtkSMPTools here and in child processes;
    call before VTK is imported."""
    if args.threads > 0:
        os.environ["VTK_SMP_MAX_THREADS"] = str(args.threads)


def print_machine(args, smp_threads=0):
    """Prints the machine, with the bandwidth measured in this run on
    @smp_threads threads (all when 0)."""
    command = [args.machine] + (["--threads", str(smp_threads)] if smp_threads > 0 else [])
    print(subprocess.run(command, check=True, stdout=subprocess.PIPE, text=True).stdout, end="", flush=True)


def sphere_with_normals(triangles):
    """A vtkSphereSource of about @triangles triangles with point normals
    (vtkPolyDataNormals, no splitting): the benches' test mesh."""
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    resolution = max(3, int(round((triangles / 2) ** 0.5)))
    source = vtkSphereSource()
    source.SetThetaResolution(resolution)
    source.SetPhiResolution(resolution + 2)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(source.GetOutputPort())
    normals.SplittingOff()
    normals.Update()
    return normals.GetOutput()
