"""Compares the MPI runs of mpi_pieces.py with the serial one (pvpython):

    pvpython compare_pieces.py SERIAL.pvtp RUN.pvtp [RUN.pvtp ...]

At every point used by a cell of a run's output (the partition boundaries
included) the run's Normals must be within 0.05 degrees of the serial ones at
the same position, and its Tangents and Radiance equal up to float rounding;
the runs must have as many cells as the serial output, no ghost cells, and
more than one non-empty piece (else nothing was partitioned). Prints one line
per run; exits non-zero on the first failure.
"""
import os
import sys
from xml.etree import ElementTree

from paraview import servermanager  # noqa: F401  (ParaView's VTK)
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from vector_angles import angle_degrees  # noqa: E402

NORMAL_DEGREES = 0.05
TANGENT_DEGREES = 1e-3      # float rounding of a sum taken in another order
RADIANCE_RELATIVE = 1e-5    # float rounding, relative to the value's size


def pieces(path):
    """The pieces of a .pvtp (its Piece Source files), each read on its own."""
    result = []
    for piece in ElementTree.parse(path).getroot().iter("Piece"):
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(os.path.join(os.path.dirname(path), piece.get("Source")))
        reader.Update()
        result.append(reader.GetOutput())
    return result


def key(mesh, i):
    return tuple(round(c, 5) for c in mesh.GetPoint(i))


def table(meshes, name):
    values = {}
    for mesh in meshes:
        array = mesh.GetPointData().GetArray(name)
        for i in range(mesh.GetNumberOfPoints()):
            values.setdefault(key(mesh, i), []).append(array.GetTuple(i))
    return values


def relative(a, b):
    return max(abs(x - y) / max(1.0, abs(y)) for x, y in zip(a, b))


def ghost_cells(mesh):
    ghosts = mesh.GetCellData().GetArray("vtkGhostType")
    return 0 if ghosts is None else sum(1 for i in range(ghosts.GetNumberOfTuples()) if ghosts.GetValue(i))


def used_points(mesh):
    conn = mesh.GetPolys().GetConnectivityArray()
    return {conn.GetValue(c) for c in range(conn.GetNumberOfValues())}


def compare(serial, run):
    checks = (("Normals", angle_degrees, NORMAL_DEGREES, False), ("Tangents", angle_degrees, TANGENT_DEGREES, True),
              ("Radiance", relative, RADIANCE_RELATIVE, False))
    tables = {name: table(serial, name) for name, _, _, _ in checks}
    serial_cells = sum(m.GetNumberOfPolys() for m in serial)
    meshes = pieces(run)
    cells = sum(m.GetNumberOfPolys() for m in meshes)
    ghosts = sum(ghost_cells(m) for m in meshes)
    non_empty = sum(1 for m in meshes if m.GetNumberOfPolys() > 0)
    worst = {name: 0.0 for name, _, _, _ in checks}
    for mesh in meshes:
        for name, measure, _, signed in checks:
            array = mesh.GetPointData().GetArray(name)
            for i in used_points(mesh):
                value = array.GetTuple(i)
                candidates = [w for w in tables[name][key(mesh, i)] if not signed or w[3] == value[3]]
                if not candidates:
                    return "%s: point %s: no serial %s with the same handedness" % (run, key(mesh, i), name)
                worst[name] = max(worst[name], min(measure(value, w) for w in candidates))
    print("%s: %d pieces (%d with cells), %d cells (serial %d), %d ghost cells, worst normal %.2e deg, "
          "tangent %.2e deg, radiance %.2e relative" % (run, len(meshes), non_empty, cells, serial_cells, ghosts,
                                                       worst["Normals"], worst["Tangents"], worst["Radiance"]))
    if non_empty < 2:
        return "%s: fewer than two pieces with cells: nothing was partitioned" % run
    if cells != serial_cells:
        return "%s: %d cells, the serial output has %d" % (run, cells, serial_cells)
    if ghosts:
        return "%s: %d ghost cells left in the output" % (run, ghosts)
    for name, _, limit, _ in checks:
        if worst[name] > limit:
            return "%s: %s differ from the serial ones by %.3g (limit %g)" % (run, name, worst[name], limit)
    return ""


def main():
    serial = pieces(sys.argv[1])
    for run in sys.argv[2:]:
        problem = compare(serial, run)
        if problem:
            sys.exit(problem)


if __name__ == "__main__":
    main()
