"""Running out of memory on a large mesh is bad input like any other: one line
"shadelab CMD: MESH: out of memory (STEP)", exit status 1, no crash, the
existing output as it was and no temporary file left. A batch reports the
mesh that did not fit and still does the others.

Each command runs under an address-space limit (RLIMIT_AS) well inside the
range where a mesh of two million triangles fails on this project's machines
(about 210 to 300 MB; the process itself takes about 110 MB), so that it
fails at some step, whichever. Before these guards: "shadelab normals:
std::bad_alloc" without the mesh, abort() when an OBJ parsing thread ran out
(std::terminate), and a batch of cosine or light whose first mesh ran out
inside the filter failed every later mesh ("UpdateInformation invoked during
another request"). Left out: render and detail, whose failures at some limits
are in Mesa's llvmpipe (SIGSEGV) and in a static initializer of a library
that OpenImageIO loads (std::terminate), outside ShadeLab."""
import os
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import unittest

from grid_meshes import write_grid_obj, write_grid_ply

SHADELAB = os.environ["SHADELAB_EXE"]
SPOT = os.path.join(os.environ["SHADELAB_DATA_DIR"], "meshes", "spot.obj")
OLD = b"old output, must survive\n"
MB = 1 << 20


def sanitized():
    """Whether the program is built with AddressSanitizer, which reserves
    terabytes of address space and cannot run under RLIMIT_AS."""
    if "libasan" in os.environ.get("LD_PRELOAD", ""):
        return True
    with open(SHADELAB, "rb") as f:
        return b"libasan.so" in f.read()


class MemoryLimitTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        if not sys.platform.startswith("linux"):
            raise unittest.SkipTest("RLIMIT_AS behaves this way on Linux only")
        if sanitized():
            raise unittest.SkipTest("AddressSanitizer cannot run under an address-space limit")
        try:
            import numpy  # noqa: F401
        except ImportError:
            raise unittest.SkipTest("needs numpy to write the large mesh")
        cls.meshes = tempfile.TemporaryDirectory(prefix="shadelab-memory-")
        cls.big_ply = os.path.join(cls.meshes.name, "big.ply")
        write_grid_ply(cls.big_ply, 1001)  # 2 000 000 triangles
        # The VTP of the same mesh, with normals: no normals to compute first.
        cls.big = os.path.join(cls.meshes.name, "big.vtp")
        r = subprocess.run([SHADELAB, "normals", cls.big_ply, "-o", cls.big], capture_output=True, text=True,
                           timeout=300)
        if r.returncode != 0:
            raise AssertionError(r.stderr)

    @classmethod
    def tearDownClass(cls):
        cls.meshes.cleanup()

    def setUp(self):
        work = tempfile.TemporaryDirectory(prefix="shadelab-memory-")
        self.addCleanup(work.cleanup)
        self.work = work.name
        shutil.copy(self.big, os.path.join(self.work, "big.vtp"))
        shutil.copy(SPOT, os.path.join(self.work, "spot.obj"))
        os.mkdir(os.path.join(self.work, "out"))

    def run_limited(self, megabytes, *args):
        def limit():
            resource.setrlimit(resource.RLIMIT_AS, (megabytes * MB, megabytes * MB))
            resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        r = subprocess.run([SHADELAB, *args], capture_output=True, text=True, timeout=300, cwd=self.work,
                           preexec_fn=limit)
        self.assertGreaterEqual(r.returncode, 0, "killed by %s: %s" % (
            signal.Signals(-r.returncode).name if r.returncode < 0 else "", r.stderr))
        return r

    def old_output(self, name):
        path = os.path.join(self.work, name)
        with open(path, "wb") as f:
            f.write(OLD)
        return path

    def assertOutOfMemory(self, r, command, mesh):
        self.assertEqual(r.returncode, 1, r.stderr)
        lines = r.stderr.splitlines()
        self.assertEqual(len(lines), 1, r.stderr)
        self.assertTrue(lines[0].startswith("shadelab %s: %s: out of memory" % (command, mesh)), r.stderr)

    def assertUnchanged(self, path):
        with open(path, "rb") as f:
            self.assertEqual(f.read(), OLD, path)

    def assertFiles(self, folder, names):
        """Exactly @p names in @p folder: no temporary file left beside them."""
        self.assertEqual(sorted(os.listdir(os.path.join(self.work, folder))), sorted(names))

    def test_each_mesh_command(self):
        cases = [
            (250, "normals", []),
            (250, "tangents", []),
            (250, "cosine", []),
            (250, "light", []),
            (250, "reference", ["--samples", "1"]),
            # Lobes on a mesh need little more than the mesh: it runs out reading it.
            (180, "lobe", []),
        ]
        for megabytes, command, options in cases:
            with self.subTest(command=command):
                out = self.old_output("out.vtp")
                r = self.run_limited(megabytes, command, "big.vtp", "-o", "out.vtp", *options)
                self.assertOutOfMemory(r, command, "big.vtp")
                self.assertUnchanged(out)
                self.assertFiles(".", ["big.vtp", "spot.obj", "out", "out.vtp"])

    def test_obj_parsing_threads(self):
        # The OBJ parser's threads: one that ran out of memory ended the
        # process (std::terminate, from about 160 to 250 MB here). Now the
        # file goes to VTK's reader, which runs out too (or, with a little
        # more memory than here, reads it).
        write_grid_obj(os.path.join(self.work, "big.obj"), 708)  # 1 000 000 triangles
        out = self.old_output("out.vtp")
        r = self.run_limited(190, "normals", "big.obj", "-o", "out.vtp")
        if r.returncode == 0:
            with open(out, "rb") as f:
                self.assertEqual(f.read(8), b"<VTKFile")
        else:
            self.assertOutOfMemory(r, "normals", "big.obj")
            self.assertUnchanged(out)
        self.assertFiles(".", ["big.obj", "big.vtp", "spot.obj", "out", "out.vtp"])

    def test_batch_goes_on_after_a_mesh_that_does_not_fit(self):
        for command in ("normals", "cosine", "light"):
            with self.subTest(command=command):
                folder = os.path.join("out", command)
                os.mkdir(os.path.join(self.work, folder))
                old = self.old_output(os.path.join(folder, "big.vtp"))
                r = self.run_limited(250, command, "big.vtp", "spot.obj", "-o", folder)
                self.assertOutOfMemory(r, command, "big.vtp")
                self.assertUnchanged(old)
                self.assertFiles(folder, ["big.vtp", "spot.vtp"])
                with open(os.path.join(self.work, folder, "spot.vtp"), "rb") as f:
                    self.assertEqual(f.read(8), b"<VTKFile")


if __name__ == "__main__":
    unittest.main()
