"""slPolyDataNormals and slPolyDataTangents on pieces of a mesh (what MPI
ranks compute in ParaView): each filter asks its input for a ghost level,
computes with the ghost cells as neighbours and removes them, so the values
at every point, piece boundaries included, are the whole mesh's. The pieces
come from vtkExtractPolyDataPiece, which makes ghost cells only on request:
nothing downstream of the filter asks for any."""
import os
import sys
import unittest

import shadelab
from vtkmodules.vtkCommonDataModel import vtkDataSetAttributes
from vtkmodules.vtkFiltersParallel import vtkExtractPolyDataPiece

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from vector_angles import angle_degrees  # noqa: E402
from vtk_errors import call_error  # noqa: E402

DATA = os.environ["SHADELAB_DATA_DIR"]


def read_spot():
    reader = shadelab.slMeshReader()
    reader.SetFileName(os.path.join(DATA, "meshes", "spot.obj"))
    reader.Update()
    return reader.GetOutput()


def by_position(mesh, name):
    """Point coordinates (rounded to float) -> list of the array's tuples there."""
    array = mesh.GetPointData().GetArray(name)
    table = {}
    for i in range(mesh.GetNumberOfPoints()):
        key = tuple(round(c, 6) for c in mesh.GetPoint(i))
        table.setdefault(key, []).append(array.GetTuple(i))
    return table


def used_points(mesh):
    ids = set()
    polys = mesh.GetPolys()
    conn = polys.GetConnectivityArray()
    for c in range(conn.GetNumberOfValues()):
        ids.add(conn.GetValue(c))
    return ids


def ghost_cells(mesh):
    ghosts = mesh.GetCellData().GetArray(vtkDataSetAttributes.GhostArrayName())
    if ghosts is None:
        return 0
    return sum(1 for i in range(ghosts.GetNumberOfTuples()) if ghosts.GetValue(i) != 0)


class PiecesTest(unittest.TestCase):
    def run_pieces(self, make_filter, mesh, pieces):
        """Yields (piece output, the filter) for each piece of @p pieces."""
        for piece in range(pieces):
            extract = vtkExtractPolyDataPiece()
            extract.SetInputData(mesh)
            f = make_filter()
            f.SetInputConnection(extract.GetOutputPort())
            self.assertEqual(call_error(f, lambda: f.UpdatePiece(piece, pieces, 0)), "")
            yield f.GetOutput()

    def compare(self, make_filter, name, tolerance_degrees, check_sign):
        mesh = read_spot()
        whole_filter = make_filter()
        whole_filter.SetInputData(mesh)
        whole_filter.Update()
        whole = by_position(whole_filter.GetOutput(), name)
        for pieces in (2, 3):
            cells = 0
            worst = 0.0
            for out in self.run_pieces(make_filter, mesh, pieces):
                self.assertEqual(ghost_cells(out), 0, "ghost cells left in the output")
                cells += out.GetNumberOfPolys()
                array = out.GetPointData().GetArray(name)
                for i in used_points(out):
                    key = tuple(round(c, 6) for c in out.GetPoint(i))
                    value = array.GetTuple(i)
                    candidates = [w for w in whole[key] if not check_sign or w[3] == value[3]]
                    self.assertTrue(candidates, "no whole-mesh value with the same sign at point %s" % (key,))
                    worst = max(worst, min(angle_degrees(value, w) for w in candidates))
            self.assertEqual(cells, mesh.GetNumberOfPolys(), "%d pieces" % pieces)
            self.assertLessEqual(worst, tolerance_degrees, "%s on %d pieces" % (name, pieces))

    def test_normals_every_weighting_with_splitting(self):
        for weighting in range(4):
            def make(weighting=weighting):
                f = shadelab.slPolyDataNormals()
                f.SetWeighting(weighting)
                return f
            self.compare(make, "Normals", 0.05, False)

    def test_tangents(self):
        self.compare(shadelab.slPolyDataTangents, "Tangents", 1e-3, True)

    def test_one_piece_keeps_input_ghost_cells(self):
        # A single piece asks for nothing and removes nothing: a caller that
        # hands in a mesh with ghost cells gets them back.
        extract = vtkExtractPolyDataPiece()
        extract.SetInputData(read_spot())
        extract.UpdatePiece(0, 2, 1)
        with_ghosts = extract.GetOutput()
        self.assertGreater(ghost_cells(with_ghosts), 0)
        f = shadelab.slPolyDataNormals()
        f.SetInputData(with_ghosts)
        f.Update()
        self.assertEqual(ghost_cells(f.GetOutput()), ghost_cells(with_ghosts))


if __name__ == "__main__":
    unittest.main()
