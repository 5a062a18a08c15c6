"""The ShadeLab::Normals filters from Python: import, run, and error messages."""
import os
import sys
import unittest

import shadelab
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from vtk_errors import update_error  # noqa: E402

DATA = os.environ["SHADELAB_DATA_DIR"]


class NormalsFromPythonTest(unittest.TestCase):
    def test_classes_are_exported(self):
        for name in ("slPolyDataNormals", "slPolyDataTangents", "slNormalMapFilter", "slBumpMapFilter",
                     "slDisplacementFilter"):
            self.assertTrue(hasattr(shadelab, name), name)

    def test_sphere_normals_point_outward(self):
        sphere = vtkSphereSource()
        sphere.SetThetaResolution(16)
        sphere.SetPhiResolution(12)
        f = shadelab.slPolyDataNormals()
        f.SetInputConnection(sphere.GetOutputPort())
        f.SetWeightingToMax()
        f.Update()
        out = f.GetOutput()
        normals = out.GetPointData().GetNormals()
        self.assertEqual(normals.GetName(), "Normals")
        for i in range(out.GetNumberOfPoints()):
            p, n = out.GetPoint(i), normals.GetTuple3(i)
            r = sum(c * c for c in p) ** 0.5
            self.assertGreater(sum(a * b for a, b in zip(p, n)) / r, 0.999)

    def test_tangents_and_normal_map_on_a_plane(self):
        plane = vtkPlaneSource()  # UVs equal (x + 0.5, y + 0.5)
        plane.SetResolution(4, 4)
        t = shadelab.slPolyDataTangents()
        t.SetInputConnection(plane.GetOutputPort())
        self.assertEqual(update_error(t), "")
        tangent = t.GetOutput().GetPointData().GetArray("Tangents").GetTuple4(0)
        for got, want in zip(tangent, (1, 0, 0, 1)):
            self.assertAlmostEqual(got, want, places=5)
        m = shadelab.slNormalMapFilter()
        m.SetInputConnection(t.GetOutputPort())
        m.SetFileName("/nonexistent/map.png")
        self.assertIn("/nonexistent/map.png", update_error(m))
        self.assertEqual(m.GetOutput().GetNumberOfPoints(), 0)


if __name__ == "__main__":
    unittest.main()
