"""Write and read times and file sizes of VTP encodings, side by side in one
run: vtkXMLPolyDataWriter with VTK's defaults (appended base64, zlib), and
slMeshWriter with each of its compressions (raw appended data; written to
memory, then to a temporary file that is synced and renamed), on a sphere
with point normals.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 bench/io/vtp_encoding.py \
        [--resolution 1000] [--runs 5] [--threads N]

Resolution 1000 gives 2,000,000 triangles. Prints the machine
(bench/common/BenchMachine, through shadelab_bench_machine), then per
encoding the median and range of the write and read times and the size.
"""
import argparse
import os
import statistics
import tempfile
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import bench_common  # noqa: E402  (bench/common)

# name, a writer for it
ENCODINGS = [
    ("vtkXMLPolyDataWriter, VTK's defaults", lambda: vtk_writer()),
    ("slMeshWriter, --compress zlib", lambda: shadelab_writer("ZLIB")),
    ("slMeshWriter, lz4 (default)", lambda: shadelab_writer("LZ4")),
    ("slMeshWriter, --compress none", lambda: shadelab_writer("NONE")),
]


def vtk_writer():
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    return vtkXMLPolyDataWriter()


def shadelab_writer(compression):
    from shadelab import slMeshWriter
    writer = slMeshWriter()
    writer.SetCompression(getattr(slMeshWriter, compression))
    return writer


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--resolution", type=int, default=1000)
    bench_common.add_arguments(parser, runs=5)
    args = parser.parse_args()
    bench_common.apply_threads(args)
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(args.resolution)
    sphere.SetPhiResolution(args.resolution + 2)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(sphere.GetOutputPort())
    normals.SplittingOff()
    normals.Update()
    mesh = normals.GetOutput()
    bench_common.print_machine(args, args.threads)
    print("%d triangles, %d runs each\n" % (mesh.GetNumberOfCells(), args.runs))
    print("| encoding | write: median (range) | read: median (range) | size |")
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "mesh.vtp")
        for name, make in ENCODINGS:
            writer = make()
            writer.SetInputData(mesh)
            writer.SetFileName(path)
            times = []
            for _ in range(args.runs):
                start = time.perf_counter()
                writer.Write()
                times.append(time.perf_counter() - start)
            reads = []
            for _ in range(args.runs):
                reader = vtkXMLPolyDataReader()
                reader.SetFileName(path)
                start = time.perf_counter()
                reader.Update()
                reads.append(time.perf_counter() - start)
            print("| %s | %.2f s (%.2f–%.2f) | %.2f s (%.2f–%.2f) | %.1f MB |" % (
                name, statistics.median(times), min(times), max(times), statistics.median(reads), min(reads),
                max(reads), os.path.getsize(path) / 1e6), flush=True)


if __name__ == "__main__":
    main()
