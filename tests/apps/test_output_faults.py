"""Outputs under faults: a full disk, stale temporary files, long names, and
extensions that do not fit what a subcommand writes. A failed write leaves
the old output byte-identical and no temporary file, and says why in one line."""
import os
import signal
import subprocess
import tempfile
import time
import unittest

from grid_meshes import write_grid_ply

SHADELAB = os.environ["SHADELAB_EXE"]
DATA = os.environ["SHADELAB_DATA_DIR"]
SPOT = os.path.join(DATA, "meshes", "spot.obj")
OLD = b"old output, must survive\n"


def run(*args, cwd=None):
    return subprocess.run([SHADELAB, *args], capture_output=True, text=True, timeout=300, cwd=cwd)


def writing_into(pid, folder):
    """Whether process @p pid holds a file of @p folder open (the output it
    writes, which has no name there yet)."""
    fds = "/proc/%d/fd" % pid
    try:
        targets = [os.readlink(os.path.join(fds, fd)) for fd in os.listdir(fds)]
    except OSError:  # it ended, or closed a descriptor while listed
        return False
    return any(target.startswith(folder + "/") for target in targets)


class FullDiskTest(unittest.TestCase):
    """Every output format of every writing subcommand on a full tmpfs."""

    @classmethod
    def setUpClass(cls):
        cls.mount = tempfile.mkdtemp(prefix="shadelab-full-")
        r = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=512k", "tmpfs", cls.mount], capture_output=True,
                           text=True)
        if r.returncode != 0:
            os.rmdir(cls.mount)
            raise unittest.SkipTest("cannot mount a tmpfs to fill (needs root): " + r.stderr.strip())

    @classmethod
    def tearDownClass(cls):
        subprocess.run(["umount", cls.mount], check=True)
        os.rmdir(cls.mount)

    def setUp(self):
        for name in os.listdir(self.mount):
            os.remove(os.path.join(self.mount, name))

    def fill(self):
        """Fills the file system to the last byte."""
        with open(os.path.join(self.mount, "filler"), "wb", buffering=0) as f:
            try:
                while True:
                    f.write(b"\0" * 4096)
            except OSError:
                pass
            try:
                while True:
                    f.write(b"\0")
            except OSError:
                pass

    def check_full_disk(self, command, outputs, *args):
        """Runs shadelab COMMAND ARGS with OUTPUTS (option -> file name) existing
        and the disk full; the first output is the one that fails."""
        paths = {}
        for option, name in outputs:
            paths[option] = os.path.join(self.mount, name)
            with open(paths[option], "wb") as f:
                f.write(OLD)
        self.fill()
        before = sorted(os.listdir(self.mount))
        options = [x for option, _ in outputs for x in (option, paths[option])]
        r = run(command, *args, *options)
        first = paths[outputs[0][0]]
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertEqual(r.stderr, "shadelab %s: %s: cannot write output file: No space left on device\n"
                         % (command, first))
        for path in paths.values():
            with open(path, "rb") as f:
                self.assertEqual(f.read(), OLD, path)
        self.assertEqual(sorted(os.listdir(self.mount)), before, "no temporary file left")

    def test_meshes(self):
        for ext in ("vtp", "ply", "obj", "vtk", "stl"):
            for command in ("normals", "light"):
                with self.subTest(command=command, ext=ext):
                    self.setUp()
                    self.check_full_disk(command, [("-o", "out." + ext)], SPOT)

    def test_images(self):
        for ext in ("png", "jpg", "jpeg", "exr", "hdr", "tif", "tiff", "bmp", "tga", "ppm"):
            with self.subTest(command="render", ext=ext):
                self.setUp()
                self.check_full_disk("render", [("-o", "out." + ext)], SPOT, "--size", "96x72")
        for ext in ("png", "jpg", "exr"):
            with self.subTest(command="cosine --image", ext=ext):
                self.setUp()
                # The image is written first, then the mesh.
                self.check_full_disk("cosine", [("--image", "img." + ext), ("-o", "out.vtp")], SPOT)

    def test_table(self):
        self.check_full_disk("lobe", [("-o", "table.csv")], "--albedo-table")


class TemporaryFileTest(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.dir = self.folder.name

    def tearDown(self):
        self.folder.cleanup()

    def test_stale_partial_files_are_removed(self):
        # Left by a killed process: ShadeLab's own naming, no live lock.
        stale = [".out.partial-a1B2c3.vtp", ".out.partial-ZZZZZZ.vtp"]
        others = [".out.partial-a1B2c3.ply", ".other.partial-a1B2c3.vtp", "out.partial-a1B2c3.vtp",
                  ".out.partial-short.vtp"]
        for name in stale + others:
            with open(os.path.join(self.dir, name), "wb") as f:
                f.write(b"half")
        r = run("normals", SPOT, "-o", os.path.join(self.dir, "out.vtp"))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(sorted(os.listdir(self.dir)), sorted(others + ["out.vtp"]),
                         "only the target's own stale temporary files go")

    def test_interrupted_write_leaves_nothing(self):
        """Ctrl-C or kill -9 while the output is being written: the old output
        as it was and no other file in its folder."""
        try:
            import numpy  # noqa: F401
        except ImportError:
            self.skipTest("needs numpy to write the large mesh")
        meshes = tempfile.TemporaryDirectory(prefix="shadelab-interrupt-")
        self.addCleanup(meshes.cleanup)
        big = os.path.join(meshes.name, "big.ply")
        write_grid_ply(big, 701)  # about a million triangles: zlib takes a while to encode them
        out = os.path.join(self.dir, "out.vtp")
        for sig in (signal.SIGINT, signal.SIGKILL):
            with self.subTest(signal=sig.name):
                with open(out, "wb") as f:
                    f.write(OLD)
                p = subprocess.Popen([SHADELAB, "normals", big, "-o", out, "--compress", "zlib"],
                                     stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
                deadline = time.monotonic() + 300
                while not writing_into(p.pid, self.dir):
                    if p.poll() is not None or time.monotonic() > deadline:
                        p.kill()
                        self.fail("the output was never seen being written: " + p.communicate()[1].decode())
                    time.sleep(0.001)
                p.send_signal(sig)
                p.communicate()
                self.assertEqual(p.returncode, -sig)
                self.assertEqual(os.listdir(self.dir), ["out.vtp"])
                with open(out, "rb") as f:
                    self.assertEqual(f.read(), OLD)

    def test_longest_names(self):
        for length in (241, 250, 255):
            for ext, args in ((".vtp", ("normals", SPOT)), (".png", ("render", SPOT, "--size", "64x48"))):
                with self.subTest(length=length, ext=ext):
                    name = "n" * (length - len(ext)) + ext
                    r = run(*args, "-o", name, cwd=self.dir)
                    self.assertEqual(r.returncode, 0, r.stderr)
                    self.assertEqual(os.listdir(self.dir), [name])
                    os.remove(os.path.join(self.dir, name))


class OutputExtensionTest(unittest.TestCase):
    """An output named for something else than what the subcommand writes
    there is refused before any work, with the extensions that would do."""
    MESH = ".vtp .vtk .ply .obj .stl"
    IMAGE = ".png .jpg .jpeg .exr .hdr .tif .tiff .bmp .tga .ppm"

    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.dir = self.folder.name

    def tearDown(self):
        self.folder.cleanup()

    def check(self, args, message):
        r = run(*args, cwd=self.dir)
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertEqual(r.stderr, message + "\n")
        self.assertEqual(os.listdir(self.dir), [])

    def test_cases(self):
        image = " (supported: %s)" % self.IMAGE
        mesh = " (supported: %s)" % self.MESH
        both = " (mesh: %s; image: %s)" % (self.MESH, self.IMAGE)
        cases = [
            (("lobe", "--albedo-table", "-o", "t.png"),
             'shadelab lobe: t.png: unsupported table format ".png" (supported: .csv)'),
            (("lobe", "-o", "t.csv"), 'shadelab lobe: t.csv: unsupported output format ".csv"' + both),
            (("lobe", "-o", "t"), "shadelab lobe: t: no file extension to tell the output format" + both),
            (("lobe", "-o", "t.vtp", "--slice", "s.png"), 'shadelab lobe: s.png: unsupported mesh format ".png"' + mesh),
            (("render", SPOT, "-o", "out.xyz"), 'shadelab render: out.xyz: unsupported image format ".xyz"' + image),
            (("render", SPOT, "-o", "out"), "shadelab render: out: no file extension to tell the image format" + image),
            (("compare", SPOT, "-o", "out.vtp"), 'shadelab compare: out.vtp: unsupported image format ".vtp"' + image),
            (("cosine", SPOT, "-o", "c.vtp", "--image", "img.xyz"),
             'shadelab cosine: img.xyz: unsupported image format ".xyz"' + image),
            (("light", SPOT, "-o", "l.png"), 'shadelab light: l.png: unsupported mesh format ".png"' + mesh),
            (("reference", SPOT, "-o", "r.csv"), 'shadelab reference: r.csv: unsupported mesh format ".csv"' + mesh),
            (("normals", SPOT, "-o", "n.png"), 'shadelab normals: n.png: unsupported mesh format ".png"' + mesh),
            (("tangents", SPOT, "-o", "n.jpg"), 'shadelab tangents: n.jpg: unsupported mesh format ".jpg"' + mesh),
            (("detail", SPOT, "-o", "d", "--bump-map", "x.png"),
             "shadelab detail: d: no file extension to tell the mesh format" + mesh),
        ]
        for args, message in cases:
            with self.subTest(args=args):
                self.check(args, message)

    def test_help_lists_the_same_extensions(self):
        for command, text in (("normals", "(%s)" % self.MESH), ("render", "(%s)" % self.IMAGE)):
            r = run(command, "--help")
            self.assertIn(text, r.stdout)


if __name__ == "__main__":
    unittest.main()
