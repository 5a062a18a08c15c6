"""`shadelab normals`, `light` and `cosine` end to end against the same job as
a short VTK script run by python3, side by side in one run: each reads a VTP
sphere, computes, and writes a VTP, as a separate process (start-up, read,
filter and write all count). The scripts use VTK's writer defaults, as a
script would; ShadeLab uses its own (LZ4). Inputs are written once with
VTK's defaults.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 bench/io/end_to_end.py \\
        [--shadelab build/bin/shadelab] [--triangles 2 8] [--runs 5]

--triangles: sizes in millions (2 and 8 by default). Prints per job and
size the median and range of both, their ratio, and the output sizes.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

SCRIPT = """import sys
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter
{imports}
r = vtkXMLPolyDataReader(); r.SetFileName(sys.argv[1])
f = {filter}; f.SetInputConnection(r.GetOutputPort())
w = vtkXMLPolyDataWriter(); w.SetInputConnection(f.GetOutputPort()); w.SetFileName(sys.argv[2]); w.Write()
"""
JOBS = {  # subcommand: (imports, filter) of the script that does the same
    "normals": ("from vtkmodules.vtkFiltersCore import vtkPolyDataNormals", "vtkPolyDataNormals()"),
    "light": ("from shadelab import slRadianceFilter", "slRadianceFilter()"),
    "cosine": ("from shadelab import slCosineField", "slCosineField()"),
}


def sphere(path, millions):
    """A VTP sphere of about @millions million triangles, with normals (the
    lighting jobs need them), written with VTK's defaults."""
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    resolution = int(round((millions * 1e6 / 2) ** 0.5))
    source = vtkSphereSource()
    source.SetThetaResolution(resolution)
    source.SetPhiResolution(resolution + 2)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(source.GetOutputPort())
    normals.SplittingOff()
    writer = vtkXMLPolyDataWriter()
    writer.SetInputConnection(normals.GetOutputPort())
    writer.SetFileName(path)
    writer.Write()
    return 2 * resolution * resolution


def timed(command):
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--shadelab", default="build/bin/shadelab")
    parser.add_argument("--triangles", type=float, nargs="+", default=[2, 8])
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()
    with open("/proc/cpuinfo") as f:
        cpu = next((line.split(":", 1)[1].strip() for line in f if line.startswith("model name")), "?")
    print("machine: %s, %d cores; %d runs each, interleaved" % (cpu, os.cpu_count(), args.runs))
    print("| job | triangles | shadelab | VTK script | ratio | output: shadelab / script |")
    print("|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for millions in args.triangles:
            mesh = os.path.join(work, "in.vtp")
            triangles = sphere(mesh, millions)
            for job, (imports, make) in JOBS.items():
                script = os.path.join(work, job + ".py")
                with open(script, "w") as f:
                    f.write(SCRIPT.format(imports=imports, filter=make))
                ours, theirs = os.path.join(work, "ours.vtp"), os.path.join(work, "theirs.vtp")
                a, b = [], []
                for _ in range(args.runs):
                    a.append(timed([args.shadelab, job, mesh, "-o", ours]))
                    b.append(timed([sys.executable, script, mesh, theirs]))
                print("| %s | %.1fM | %.2f s (%.2f–%.2f) | %.2f s (%.2f–%.2f) | %.2f× | %.0f MB / %.0f MB |" % (
                    job, triangles / 1e6, statistics.median(a), min(a), max(a), statistics.median(b), min(b), max(b),
                    statistics.median(b) / statistics.median(a), os.path.getsize(ours) / 1e6,
                    os.path.getsize(theirs) / 1e6), flush=True)


if __name__ == "__main__":
    main()
