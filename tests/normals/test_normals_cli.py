"""shadelab normals: output arrays, splitting, and one-line errors with no partial output."""
import os
import subprocess
import sys
import tempfile
import unittest

SHADELAB = os.environ["SHADELAB_EXE"]
SHARED = os.environ["SHADELAB_SHARED_DATA_DIR"]
FANDISK = os.path.join(SHARED, "meshes", "fandisk.obj")

from vtkmodules.vtkIOXML import vtkXMLPolyDataReader  # noqa: E402


def run(*args):
    return subprocess.run([SHADELAB, *args], capture_output=True, text=True, timeout=120)


def read_vtp(path):
    r = vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    return r.GetOutput()


class NormalsCommandTest(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.folder.cleanup()

    def path(self, name):
        return os.path.join(self.folder.name, name)

    def test_writes_point_and_cell_normals_and_splits_sharp_edges(self):
        split, smooth = self.path("split.vtp"), self.path("smooth.vtp")
        self.assertEqual(run("normals", FANDISK, "-o", split, "--cells").returncode, 0)
        self.assertEqual(run("normals", FANDISK, "-o", smooth, "--no-split").returncode, 0)
        a, b = read_vtp(split), read_vtp(smooth)
        self.assertEqual(a.GetPointData().GetNormals().GetName(), "Normals")
        self.assertEqual(a.GetCellData().GetNormals().GetNumberOfTuples(), 12946)
        self.assertIsNone(b.GetCellData().GetNormals())
        self.assertGreater(a.GetNumberOfPoints(), b.GetNumberOfPoints())
        self.assertEqual(a.GetNumberOfPolys(), b.GetNumberOfPolys())

    def test_bad_input_gives_one_line_and_no_output(self):
        out = self.path("out.vtp")
        cases = [
            (("normals", "/nonexistent/m.obj", "-o", out), 1, "/nonexistent/m.obj: "),
            (("normals", FANDISK, "-o", out, "--weighting", "cotan"), 2, "--weighting"),
            (("normals", FANDISK, "-o", out, "--feature-angle", "200"), 2, "feature-angle"),
            (("normals", FANDISK), 2, "--output"),
        ]
        for args, status, text in cases:
            r = run(*args)
            self.assertEqual(r.returncode, status, args)
            self.assertEqual(r.stderr.count("\n"), 1, r.stderr)
            self.assertIn(text, r.stderr)
            self.assertFalse(os.path.exists(out))


if __name__ == "__main__":
    unittest.main()
