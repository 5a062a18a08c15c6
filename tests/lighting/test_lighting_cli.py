"""shadelab cosine / light / lobe / reference: help, outputs, one-line errors."""
import os
import subprocess
import sys
import tempfile
import unittest

SHADELAB = os.environ["SHADELAB_EXE"]
DATA = os.environ["SHADELAB_DATA_DIR"]
SPOT = os.path.join(os.environ["SHADELAB_DATA_DIR"], "meshes", "spot.obj")
VENICE = os.path.join(DATA, "envmaps", "venice_sunset_1k.hdr")


def run(*args):
    return subprocess.run([SHADELAB, *args], capture_output=True, text=True, timeout=120)


class LightingCommandsTest(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.folder.cleanup()

    def out(self, name):
        return os.path.join(self.folder.name, name)

    def test_help(self):
        for command in ("cosine", "light", "lobe", "reference"):
            r = run(command, "--help")
            self.assertEqual(r.returncode, 0, command)
            self.assertIn("usage: shadelab " + command, r.stdout)

    def test_jobs_write_their_outputs(self):
        jobs = [
            ["cosine", SPOT, "-o", self.out("c.vtp")],
            ["light", SPOT, "--per-light", "-o", self.out("l.vtp")],
            ["lobe", "--model", "phong", "-o", self.out("lobe.vtp"), "--slice", self.out("slice.vtp")],
            ["lobe", SPOT, "--points", "4", "-o", self.out("lobes.vtp")],
            ["lobe", "--albedo-table", "-o", self.out("albedo.csv")],
            ["reference", SPOT, "--envmap", VENICE, "--samples", "4", "-o", self.out("r.vtp")],
        ]
        for job in jobs:
            r = run(*job)
            self.assertEqual(r.returncode, 0, (job, r.stderr))
            self.assertTrue(os.path.getsize(job[job.index("-o") + 1]) > 0, job)
        with open(self.out("albedo.csv")) as f:
            self.assertTrue(f.readline().startswith("IncidenceDegrees,lambert,phong"))

    def test_bad_input_is_one_line_and_non_zero(self):
        bad = self.out("bad.hdr")
        with open(bad, "w") as f:
            f.write("not an image")
        empty = self.out("empty.obj")
        with open(empty, "w") as f:
            f.write("# nothing\n")
        no_lights = self.out("dark.json")
        with open(no_lights, "w") as f:
            f.write('{"lights": []}')
        cases = [
            (["light", SPOT, "--scene", no_lights, "-o", self.out("x.vtp")], "dark.json: lights: it has no lights"),
            (["light", SPOT, "-o", self.out("x.vtp"), "--scene", self.out("missing.json")], "missing.json"),
            (["reference", SPOT, "--envmap", bad, "-o", self.out("x.vtp")], "bad.hdr: cannot read image"),
            (["reference", SPOT, "--envmap", os.path.join(DATA, "meshes", "spot_texture.png"), "-o",
              self.out("x.vtp")], "twice as wide as it is high"),
            (["cosine", empty, "-o", self.out("x.vtp")], "empty.obj"),
            (["reference", SPOT, "--sampling", "magic", "-o", self.out("x.vtp")], "--sampling"),
        ]
        for args, text in cases:
            r = run(*args)
            self.assertNotEqual(r.returncode, 0, args)
            self.assertEqual(r.stderr.count("\n"), 1, (args, r.stderr))
            self.assertIn(text, r.stderr, args)
            self.assertFalse(os.path.exists(self.out("x.vtp")), args)


if __name__ == "__main__":
    sys.exit(unittest.main())
