"""`shadelab normals|light|cosine MESH... -o FOLDER`: each mesh gives the file
a run of its own would give, a failing mesh is one line and does not stop
the others, and name clashes and misuse are refused before any work."""
import itertools
import os
import struct
import subprocess
import tempfile
import unittest

SHADELAB = os.environ["SHADELAB_EXE"]
SPOT = os.path.join(os.environ["SHADELAB_DATA_DIR"], "meshes", "spot.obj")
TETRA = b"OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
BAD = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"
# Three points in uncompressed appended data, under a negative point count.
NEGATIVE_VTP = (b'<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian" header_type="UInt32">\n'
                b'<PolyData>\n<Piece NumberOfPoints="-1" NumberOfPolys="0">\n<Points><DataArray type="Float32" '
                b'Name="Points" NumberOfComponents="3" format="appended" offset="0"/></Points>\n</Piece>\n'
                b'</PolyData>\n<AppendedData encoding="raw">\n_' + struct.pack("<I9f", 36, 0, 0, 0, 1, 0, 0, 0, 1, 0) +
                b'\n</AppendedData>\n</VTKFile>\n')


COMMANDS = {"normals": ["--weighting", "area"], "light": ["--model", "phong"], "cosine": ["--no-cells"]}


def shadelab(command, *args, cwd):
    return subprocess.run([SHADELAB, command, *args], capture_output=True, text=True, timeout=300, cwd=cwd)


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
        # Uncompressed too: then a difference is found at its byte, and the
        # header says which array holds it.
        for (command, options), compress in itertools.product(COMMANDS.items(), ("lz4", "none")):
            with self.subTest(command=command, compress=compress):
                options = [*options, "--compress", compress]
                out = os.path.join(self.work, command + "-" + compress)
                os.mkdir(out)
                r = shadelab(command, SPOT, "bad.obj", "tet.off", "-o", out, *options, cwd=self.work)
                self.assertEqual(r.returncode, 1)
                self.assertEqual(r.stderr,
                                 "shadelab %s: bad.obj: line 4: vertex index 9 is out of range [1, 3]\n" % command)
                self.assertEqual(sorted(os.listdir(out)), ["spot.vtp", "tet.vtp"])
                for mesh, name in ((SPOT, "spot"), ("tet.off", "tet")):
                    single = shadelab(command, mesh, "-o", name + ".vtp", *options, cwd=self.work)
                    self.assertEqual(single.returncode, 0, single.stderr)
                    self.assertSameBytes(os.path.join(self.work, name + ".vtp"), os.path.join(out, name + ".vtp"))

    def assertSameBytes(self, one, batch):
        with open(one, "rb") as f:
            a = f.read()
        with open(batch, "rb") as f:
            b = f.read()
        if a == b:
            return
        at = next((i for i, (x, y) in enumerate(zip(a, b)) if x != y), min(len(a), len(b)))
        header = a[:a.find(b"<AppendedData")].decode("latin-1")
        appended = a.find(b"<AppendedData")
        appended = a.find(b"_", appended) + 1 if appended >= 0 else -1
        self.fail("%s differs from its single run's file (%d and %d bytes) at byte %d%s: %r against %r\n%s" % (
            batch, len(b), len(a), at, " (appended data offset %d)" % (at - appended) if 0 <= appended <= at else "",
            a[max(0, at - 8):at + 24], b[max(0, at - 8):at + 24], header))

    def test_format_names_the_outputs(self):
        r = shadelab("normals", SPOT, "tet.off", "-o", "out", "--format", "ply", cwd=self.work)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(sorted(os.listdir(os.path.join(self.work, "out"))), ["spot.ply", "tet.ply"])

    def test_a_file_vtk_would_crash_on_does_not_stop_the_rest(self):
        # VTK's XML reader read the data before the array's start, and the
        # crash took the meshes after it with it.
        with open(os.path.join(self.work, "neg.vtp"), "wb") as f:
            f.write(NEGATIVE_VTP)
        r = shadelab("normals", "neg.vtp", "tet.off", "-o", "out", cwd=self.work)
        self.assertEqual(r.returncode, 1)
        self.assertEqual(r.stderr, "shadelab normals: neg.vtp: NumberOfPoints=-1 is negative\n")
        self.assertEqual(os.listdir(os.path.join(self.work, "out")), ["tet.vtp"])

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
        cosine = [((SPOT, "tet.off", "-o", "out", "--image", "one.png"), "--image: only with one MESH (got 2)")]
        for command, args, message in [("normals", *c) for c in cases] + [("cosine", *c) for c in cosine]:
            with self.subTest(args=args):
                r = shadelab(command, *args, cwd=self.work)
                self.assertEqual(r.returncode, 2)
                self.assertTrue(r.stderr.startswith("shadelab %s: " % command) and r.stderr.endswith(message + "\n"),
                                r.stderr)
                self.assertEqual(r.stderr.count("\n"), 1)
                self.assertEqual(os.listdir(os.path.join(self.work, "out")), [])
                self.assertFalse(os.path.exists(os.path.join(self.work, "one.vtp")))
                self.assertFalse(os.path.exists(os.path.join(self.work, "one.png")))


if __name__ == "__main__":
    unittest.main()
