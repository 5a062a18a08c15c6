"""Write and read times and file sizes of VTP encodings, side by side in one
run: vtkXMLPolyDataWriter with VTK's defaults (appended base64, zlib), and
slMeshWriter with each of its compressions (raw appended data; written to
memory, then to a temporary file that is synced and renamed), on a sphere
with point normals.

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 bench/io/vtp_encoding.py \
        [--resolution 1000] [--runs 3]

Resolution 1000 gives 2,000,000 triangles. Prints the median and range of
the write times, one read time and the size, and the machine.
"""
import argparse
import os
import platform
import statistics
import tempfile
import time

from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

from shadelab import slMeshWriter

# name, a writer for it
ENCODINGS = [
    ("vtkXMLPolyDataWriter, VTK's defaults", lambda: vtkXMLPolyDataWriter()),
    ("slMeshWriter, --compress zlib", lambda: shadelab_writer(slMeshWriter.ZLIB)),
    ("slMeshWriter, lz4 (default)", lambda: shadelab_writer(slMeshWriter.LZ4)),
    ("slMeshWriter, --compress none", lambda: shadelab_writer(slMeshWriter.NONE)),
]


def shadelab_writer(compression):
    writer = slMeshWriter()
    writer.SetCompression(compression)
    return writer


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--resolution", type=int, default=1000)
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(args.resolution)
    sphere.SetPhiResolution(args.resolution + 2)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(sphere.GetOutputPort())
    normals.SplittingOff()
    normals.Update()
    mesh = normals.GetOutput()
    with open("/proc/cpuinfo") as f:
        cpu = next((line.split(":", 1)[1].strip() for line in f if line.startswith("model name")), platform.processor())
    print("machine: %s, %d cores; %d triangles, %d runs each" % (cpu, os.cpu_count(), mesh.GetNumberOfCells(),
                                                                 args.runs))
    print("| encoding | write: median (range) | read | size |")
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
            reader = vtkXMLPolyDataReader()
            reader.SetFileName(path)
            start = time.perf_counter()
            reader.Update()
            read = time.perf_counter() - start
            print("| %s | %.2f s (%.2f–%.2f) | %.2f s | %.1f MB |" % (
                name, statistics.median(times), min(times), max(times), read, os.path.getsize(path) / 1e6))


if __name__ == "__main__":
    main()
