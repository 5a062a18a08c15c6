"""Writes an OBJ's triangles as a VTP for the ParaView tests (pvpython).

ParaView's OBJ reader gives every triangle its own points, so a partition
boundary would not share points; this keeps one point per distinct
(position, texture coordinate) pair, as slMeshReader does. The VTP is
inline binary: ParaView 5.11's XML reader cannot read the appended layout
with Debian 12's libexpat (test_libexpat.py).

    pvpython obj_to_vtp.py MESH.obj OUT.vtp
"""
import sys

from paraview import vtk  # noqa: F401  (ParaView's VTK)
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter


def read_obj(path):
    positions, uvs, corners = [], [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                positions.append(tuple(float(x) for x in parts[1:4]))
            elif parts[0] == "vt":
                uvs.append(tuple(float(x) for x in parts[1:3]))
            elif parts[0] == "f":
                face = []
                for c in parts[1:]:
                    ids = c.split("/")
                    v = int(ids[0]) - 1
                    t = int(ids[1]) - 1 if len(ids) > 1 and ids[1] else -1
                    face.append((v, t))
                for i in range(1, len(face) - 1):
                    corners.append((face[0], face[i], face[i + 1]))
    return positions, uvs, corners


def main(source, target):
    positions, uvs, triangles = read_obj(source)
    index = {}
    points = vtkPoints()
    tcoords = vtkFloatArray()
    tcoords.SetName("TCoords")
    tcoords.SetNumberOfComponents(2)
    polys = vtkCellArray()
    for triangle in triangles:
        polys.InsertNextCell(3)
        for key in triangle:
            if key not in index:
                index[key] = points.InsertNextPoint(positions[key[0]])
                tcoords.InsertNextTuple(uvs[key[1]] if key[1] >= 0 else (0.0, 0.0))
            polys.InsertCellPoint(index[key])
    mesh = vtkPolyData()
    mesh.SetPoints(points)
    mesh.SetPolys(polys)
    mesh.GetPointData().SetTCoords(tcoords)
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(mesh)
    writer.SetDataModeToBinary()
    writer.SetFileName(target)
    if not writer.Write():
        sys.exit("%s: cannot write" % target)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
