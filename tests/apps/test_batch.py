"""`shadelab normals MESH... -o FOLDER`: each mesh gives the file a run of its
own would give, a failing mesh is one line and does not stop the others,
and name clashes and misuse are refused before any work."""
import filecmp
import os
import subprocess
import tempfile
import unittest

SHADELAB = os.environ["SHADELAB_EXE"]
SPOT = os.path.join(os.environ["SHADELAB_DATA_DIR"], "meshes", "spot.obj")
TETRA = b"OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
BAD = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"


def normals(*args, cwd):
    return subprocess.run([SHADELAB, "normals", *args], capture_output=True, text=True, timeout=300, cwd=cwd)


class BatchTest(unittest.TestCase):
    def setUp(self):
        work = tempfile.TemporaryDirectory(prefix="shadelab-batch-")
        self.addCleanup(work.cleanup)
        self.work = work.name
        for name, data in (("tet.off", TETRA), ("bad.obj", BAD)):
            with open(os.path.join(self.work, name), "wb") as f:
                f.write(data)
        os.mkdir(os.path.join(self.work, "out"))

    def test_each_mesh_as_its_own_run_and_failures_do_not_stop_the_rest(self):
        r = normals(SPOT, "bad.obj", "tet.off", "-o", "out", "--weighting", "area", cwd=self.work)
        self.assertEqual(r.returncode, 1)
        self.assertEqual(r.stderr, "shadelab normals: bad.obj: line 4: vertex index 9 is out of range [1, 3]\n")
        self.assertEqual(sorted(os.listdir(os.path.join(self.work, "out"))), ["spot.vtp", "tet.vtp"])
        for mesh, name in ((SPOT, "spot"), ("tet.off", "tet")):
            single = normals(mesh, "-o", name + ".vtp", "--weighting", "area", cwd=self.work)
            self.assertEqual(single.returncode, 0, single.stderr)
            self.assertTrue(filecmp.cmp(os.path.join(self.work, name + ".vtp"),
                                        os.path.join(self.work, "out", name + ".vtp"), shallow=False), name)

    def test_format_names_the_outputs(self):
        r = normals(SPOT, "tet.off", "-o", "out", "--format", "ply", cwd=self.work)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(sorted(os.listdir(os.path.join(self.work, "out"))), ["spot.ply", "tet.ply"])

    def test_misuse_is_refused_before_any_work(self):
        with open(os.path.join(self.work, "spot.off"), "wb") as f:
            f.write(TETRA)
        cases = [
            ((SPOT, "spot.off", "-o", "out"), "spot.off would both write out/spot.vtp"),
            ((SPOT, "tet.off", "-o", "one.vtp"), '-o/--output: with 2 MESH arguments, "one.vtp" must be an existing folder'),
            ((SPOT, "-o", "one.vtp", "--format", "ply"), '--format: only with -o FOLDER ("one.vtp" is not a folder)'),
            ((SPOT, "-o", "out", "--format", "png"),
             '--format .png: unsupported mesh format ".png" (supported: .vtp .vtk .ply .obj .stl)'),
        ]
        for args, message in cases:
            with self.subTest(args=args):
                r = normals(*args, cwd=self.work)
                self.assertEqual(r.returncode, 2)
                self.assertTrue(r.stderr.startswith("shadelab normals: ") and r.stderr.endswith(message + "\n"),
                                r.stderr)
                self.assertEqual(r.stderr.count("\n"), 1)
                self.assertEqual(os.listdir(os.path.join(self.work, "out")), [])
                self.assertFalse(os.path.exists(os.path.join(self.work, "one.vtp")))


if __name__ == "__main__":
    unittest.main()
