"""What the I/O benches share: the machine they run on, printed by
shadelab_bench_machine (bench/common/BenchMachine: CPU model, cores,
threads, memory, load, and the memory bandwidth measured now), and the
--threads option, which reaches vtkSMPTools in this process and in every
program run from it through VTK_SMP_MAX_THREADS."""
import os
import subprocess


def add_arguments(parser, runs):
    """--runs, --threads and --machine, as every ShadeLab bench takes them."""
    parser.add_argument("--runs", type=int, default=runs,
                        help="runs of each measurement; the median and range are reported (default %d)" % runs)
    parser.add_argument("--threads", type=int, default=0,
                        help="threads for vtkSMPTools (default: all %d cores)" % os.cpu_count())
    parser.add_argument("--machine", default="build/bin/shadelab_bench_machine",
                        help="the program that describes the machine (default %(default)s)")


def apply_threads(args):
    """Sets the thread count for vtkSMPTools here and in child processes;
    call before VTK is imported."""
    if args.threads > 0:
        os.environ["VTK_SMP_MAX_THREADS"] = str(args.threads)


def print_machine(args):
    """Prints the machine, with the bandwidth measured in this run."""
    command = [args.machine] + (["--threads", str(args.threads)] if args.threads > 0 else [])
    print(subprocess.run(command, check=True, stdout=subprocess.PIPE, text=True).stdout, end="", flush=True)
