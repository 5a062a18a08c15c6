"""`shadelab normals`, `light` and `cosine` end to end against the same job as
a short VTK script run by python3, side by side in one run: each reads a
sphere, computes, and writes the result in the same format, as a separate
process (start-up, read, compute and write all count). VTP in and out for
the three commands; binary PLY and OBJ in and out for `normals` (the
lighting arrays do not fit those formats). The scripts use VTK's readers
and writers with their defaults (binary PLY), as a script would; ShadeLab
uses its own (VTP: LZ4). Inputs are written once by VTK's writers, with
point normals (the lighting jobs need them).

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 bench/io/end_to_end.py \\
        [--shadelab build/bin/shadelab] [--triangles 2 8] [--formats vtp ply obj] [--runs 5] [--threads N]

Prints the machine (bench/common/BenchMachine, through
shadelab_bench_machine), then per job, format and size the median and
range of both over the runs (interleaved), their ratio, and the output
sizes.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import bench_common  # noqa: E402  (bench/common)

SCRIPT = """import sys
{imports}
r = {reader}(); r.SetFileName(sys.argv[1])
f = {filter}; f.SetInputConnection(r.GetOutputPort())
w = {writer}(); w.SetInputConnection(f.GetOutputPort()); w.SetFileName(sys.argv[2]){binary}; w.Write()
"""
FORMATS = {  # extension: (imports, reader, writer, writer options)
    "vtp": ("from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter", "vtkXMLPolyDataReader",
            "vtkXMLPolyDataWriter", ""),
    "ply": ("from vtkmodules.vtkIOPLY import vtkPLYReader, vtkPLYWriter", "vtkPLYReader", "vtkPLYWriter",
            "; w.SetFileTypeToBinary()"),
    "obj": ("from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkOBJWriter", "vtkOBJReader", "vtkOBJWriter", ""),
}
JOBS = {  # subcommand: (imports, filter, formats) of the script that does the same
    "normals": ("from vtkmodules.vtkFiltersCore import vtkPolyDataNormals", "vtkPolyDataNormals()",
                ("vtp", "ply", "obj")),
    "light": ("from shadelab import slRadianceFilter", "slRadianceFilter()", ("vtp",)),
    "cosine": ("from shadelab import slCosineField", "slCosineField()", ("vtp",)),
}


def sphere(folder, millions, formats):
    """A sphere of about @millions million triangles with point normals,
    written by VTK's writers in each of @formats; returns its triangles."""
    from vtkmodules.vtkIOGeometry import vtkOBJWriter
    from vtkmodules.vtkIOPLY import vtkPLYWriter
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    mesh = bench_common.sphere_with_normals(millions * 1e6)
    for ext in formats:
        writer = {"vtp": vtkXMLPolyDataWriter, "ply": vtkPLYWriter, "obj": vtkOBJWriter}[ext]()
        if ext == "ply":
            writer.SetFileTypeToBinary()
        writer.SetInputData(mesh)
        writer.SetFileName(os.path.join(folder, "in." + ext))
        writer.Write()
    return mesh.GetNumberOfCells()


def timed(command):
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def spread(times):
    return "%.2f s (%.2f–%.2f)" % (statistics.median(times), min(times), max(times))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--shadelab", default="build/bin/shadelab")
    parser.add_argument("--triangles", type=float, nargs="+", default=[2, 8], help="sizes in millions (default 2 8)")
    parser.add_argument("--formats", nargs="+", default=list(FORMATS), choices=list(FORMATS),
                        help="formats in and out (default: all)")
    bench_common.add_arguments(parser, runs=5)
    args = parser.parse_args()
    bench_common.apply_threads(args)
    bench_common.print_machine(args, args.threads)
    print("%d runs each, shadelab and the script interleaved\n" % args.runs)
    print("| job | format | triangles | shadelab | VTK script | ratio | output: shadelab / script |")
    print("|---|---|---|---|---|---|---|", flush=True)
    with tempfile.TemporaryDirectory() as work:
        for millions in args.triangles:
            triangles = sphere(work, millions, args.formats)
            for job, (imports, make, formats) in JOBS.items():
                for ext in (f for f in formats if f in args.formats):
                    io_imports, reader, writer, options = FORMATS[ext]
                    script = os.path.join(work, "%s-%s.py" % (job, ext))
                    with open(script, "w") as f:
                        f.write(SCRIPT.format(imports=io_imports + "\n" + imports, reader=reader, filter=make,
                                              writer=writer, binary=options))
                    mesh = os.path.join(work, "in." + ext)
                    ours, theirs = os.path.join(work, "ours." + ext), os.path.join(work, "theirs." + ext)
                    a, b = [], []
                    for _ in range(args.runs):
                        a.append(timed([args.shadelab, job, mesh, "-o", ours]))
                        b.append(timed([sys.executable, script, mesh, theirs]))
                    print("| %s | %s | %.1fM | %s | %s | %.2f× | %.0f MB / %.0f MB |" % (
                        job, ext.upper(), triangles / 1e6, spread(a), spread(b),
                        statistics.median(b) / statistics.median(a), os.path.getsize(ours) / 1e6,
                        os.path.getsize(theirs) / 1e6), flush=True)
                    os.remove(ours)
                    os.remove(theirs)


if __name__ == "__main__":
    main()
