"""GLX context creation that fails, as it does for a moment when many
processes start rendering on one X server, and X connections that fail, as
they do while an Xvfb without -noreset resets after its last client left. A
shim preloaded into `shadelab render` (glx_fault_shim.c) makes chosen
attempts fail: a passing failure is retried and the render succeeds; a
lasting one, before VTK tries or when VTK tries, is one line and exit status
1, never abort() (VTK 9.1's reaction), and the existing output stays as it
was. The render opens one connection only, so a server that refuses every
connection after the first one still renders."""
import os
import subprocess
import tempfile
import unittest

SHADELAB = os.environ["SHADELAB_EXE"]
SHIM = os.environ["SHADELAB_GLX_FAULT_SHIM"]
SPOT = os.path.join(os.environ["SHADELAB_DATA_DIR"], "meshes", "spot.obj")
OLD = b"old image, must survive\n"


class GLXFaultTest(unittest.TestCase):
    def render(self, failing, failing_connections=""):
        """shadelab render with context creation attempts FIRST .. FIRST+COUNT-1
        failing (@failing = "FIRST COUNT"; COUNT -1: all from FIRST on), and
        connection attempts as @failing_connections says, over an existing output."""
        self.work = tempfile.TemporaryDirectory(prefix="shadelab-glx-")
        self.addCleanup(self.work.cleanup)
        self.out = os.path.join(self.work.name, "out.png")
        with open(self.out, "wb") as f:
            f.write(OLD)
        # After what is preloaded already: a sanitizer's runtime must come first.
        preload = " ".join(p for p in (os.environ.get("LD_PRELOAD", ""), SHIM) if p)
        env = dict(os.environ, LD_PRELOAD=preload, SHADELAB_GLX_FAIL=failing,
                   SHADELAB_XOPEN_FAIL=failing_connections)
        return subprocess.run([SHADELAB, "render", SPOT, "--size", "64x64", "-o", self.out], env=env,
                              capture_output=True, text=True, timeout=120)

    def assertFailedInOneLine(self, r, message):
        self.assertEqual(r.returncode, 1, r.stderr)  # abort() would be -6
        self.assertEqual(r.stderr, "shadelab render: " + message + "\n")
        with open(self.out, "rb") as f:
            self.assertEqual(f.read(), OLD)
        self.assertEqual(os.listdir(self.work.name), ["out.png"])

    def assertRendered(self, r):
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(self.out, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")

    def test_passing_failures_are_retried(self):
        self.assertRendered(self.render("0 3"))

    def test_passing_connection_failures_are_retried(self):
        self.assertRendered(self.render("", "0 2"))

    def test_one_connection_for_the_whole_render(self):
        # Every connection after the check's fails: VTK must render on the
        # check's connection (it would abort() on a failed one of its own).
        self.assertRendered(self.render("", "1 -1"))

    def test_lasting_connection_failure_is_one_line(self):
        display = os.environ.get("DISPLAY", "")
        self.assertFailedInOneLine(self.render("", "0 -1"), "cannot create an OpenGL context on X display " +
                                   display + " (6 attempts): cannot connect to the X server")

    def test_lasting_failure_is_one_line(self):
        display = os.environ.get("DISPLAY", "")
        self.assertFailedInOneLine(self.render("0 -1"), "cannot create an OpenGL context on X display " + display +
                                   " (6 attempts): GLX context creation failed")

    def test_failure_when_vtk_tries_is_one_line(self):
        # The check before VTK succeeds (attempt 0); every attempt of VTK's fails.
        self.assertFailedInOneLine(self.render("1 -1"), "VTK cannot create an OpenGL context on the X display")


if __name__ == "__main__":
    unittest.main()
