"""shadelab normals: output arrays, splitting, and one-line errors with no partial output."""
import os
import subprocess
import sys
import tempfile
import unittest

SHADELAB = os.environ["SHADELAB_EXE"]
DATA = os.environ["SHADELAB_DATA_DIR"]
FANDISK = os.path.join(DATA, "meshes", "fandisk.obj")

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

    def test_summary_line_counts_in_words(self):
        # One triangle: "1 polygon", not "1 polygons"; fandisk's counts (its
        # OBJ holds 6475 points and 12946 triangles) in the plural.
        triangle, out = self.path("t.obj"), self.path("t.vtp")
        with open(triangle, "w") as f:
            f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
        r = run("normals", triangle, "-o", out)
        self.assertEqual(r.stdout, f"wrote {out}: 3 points (0 added along sharp edges), 1 polygon, 0 reversed, "
                                   "weighting angle\n")
        r = run("normals", FANDISK, "-o", out, "--no-split")
        self.assertIn(": 6475 points (0 added along sharp edges), 12946 polygons, ", r.stdout)

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


class TangentsAndDetailCommandTest(unittest.TestCase):
    SPOT = os.path.join(DATA, "meshes", "spot.obj")
    NORMAL_MAP = os.path.join(DATA, "textures", "bevy_parallax_cube_normal.png")
    DEPTH_MAP = os.path.join(DATA, "textures", "bevy_parallax_cube_depth.png")

    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.out = os.path.join(self.folder.name, "out.vtp")

    def tearDown(self):
        self.folder.cleanup()

    def test_tangents_and_each_detail_mode_write_their_arrays(self):
        self.assertEqual(run("tangents", self.SPOT, "-o", self.out).returncode, 0)
        t = read_vtp(self.out).GetPointData().GetArray("Tangents")
        self.assertEqual(t.GetNumberOfComponents(), 4)
        for args in (("--normal-map", self.NORMAL_MAP, "--directx"), ("--bump-map", self.DEPTH_MAP, "--invert"),
                     ("--displace", self.DEPTH_MAP, "--scale", "0.02")):
            r = run("detail", self.SPOT, "-o", self.out, *args)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIsNotNone(read_vtp(self.out).GetPointData().GetNormals())
            os.remove(self.out)

    def test_bad_input_gives_one_line_and_no_output(self):
        bad = os.path.join(self.folder.name, "bad.png")
        with open(bad, "w") as f:
            f.write("not a png")
        cases = [
            (("tangents", FANDISK, "-o", self.out), 1, "no texture coordinates"),
            (("detail", FANDISK, "-o", self.out, "--bump-map", self.DEPTH_MAP), 1, "no texture coordinates"),
            (("detail", self.SPOT, "-o", self.out, "--normal-map", bad), 1, bad),
            (("detail", self.SPOT, "-o", self.out, "--displace", "/nonexistent/h.png"), 1, "/nonexistent/h.png"),
            (("detail", self.SPOT, "-o", self.out), 2, "exactly one of"),
            (("detail", self.SPOT, "-o", self.out, "--normal-map", self.NORMAL_MAP, "--strength", "11"), 2, "strength"),
        ]
        for args, status, text in cases:
            r = run(*args)
            self.assertEqual(r.returncode, status, args)
            self.assertEqual(r.stderr.count("\n"), 1, r.stderr)
            self.assertIn(text, r.stderr)
            self.assertFalse(os.path.exists(self.out))


if __name__ == "__main__":
    unittest.main()
