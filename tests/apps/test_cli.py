"""The shadelab command line: the render job, and one-line errors for bad input."""
import os
import subprocess
import tempfile
import unittest

SHADELAB = os.environ["SHADELAB_EXE"]
DATA = os.environ["SHADELAB_DATA_DIR"]
SPOT = os.path.join(DATA, "meshes", "spot.obj")


def run(*args):
    return subprocess.run([SHADELAB, *args], capture_output=True, text=True, timeout=120)


def lighting_models():
    """The lighting models as `shadelab render --help` lists them, from LightingTables.h."""
    text = run("render", "--help").stdout
    return next(line for line in text.splitlines() if "--model NAME" in line).split("lighting model: ", 1)[1].strip()


def png_size(path):
    with open(path, "rb") as f:
        header = f.read(24)
    assert header[:8] == b"\x89PNG\r\n\x1a\n", path
    return int.from_bytes(header[16:20], "big"), int.from_bytes(header[20:24], "big")


class HelpTest(unittest.TestCase):
    def test_help(self):
        for args in (["--help"], ["render", "--help"]):
            r = run(*args)
            self.assertEqual(r.returncode, 0, args)
            self.assertIn("usage: shadelab", r.stdout)

    def test_unknown_subcommand(self):
        r = run("paint")
        self.assertEqual(r.returncode, 2)
        self.assertEqual(r.stderr, 'shadelab: unknown subcommand "paint" (see shadelab --help)\n')


class RenderTest(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.out = os.path.join(self.folder.name, "out.png")

    def tearDown(self):
        self.folder.cleanup()

    def write(self, name, text):
        path = os.path.join(self.folder.name, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def assert_one_line_failure(self, result, starts_with):
        self.assertNotEqual(result.returncode, 0)
        self.assertEqual(result.stderr.count("\n"), 1, result.stderr)
        self.assertTrue(result.stderr.startswith(starts_with), result.stderr)

    def test_default_scene(self):
        r = run("render", SPOT, "--scene", os.path.join(DATA, "scenes", "default.json"), "-o", self.out, "-q")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(png_size(self.out), (800, 600))
        self.assertEqual(os.listdir(self.folder.name), ["out.png"], "no temporary file left")

    def test_builtin_scene_size_and_formats(self):
        for mesh in ("fandisk.obj", "teapot.obj"):
            r = run("render", os.path.join(DATA, "meshes", mesh), "--size", "64x48", "-o", self.out)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(png_size(self.out), (64, 48))

    def test_missing_mesh(self):
        r = run("render", "/nonexistent/cow.obj", "-o", self.out)
        self.assertEqual(r.returncode, 1)
        self.assertEqual(r.stderr, "shadelab render: /nonexistent/cow.obj: cannot open file\n")
        self.assertFalse(os.path.exists(self.out))

    def test_unreadable_mesh_keeps_existing_output(self):
        with open(self.out, "wb") as f:
            f.write(b"previous image")
        junk = self.write("junk.ply", "ply\nformat nonsense\n")
        r = run("render", junk, "-o", self.out)
        self.assert_one_line_failure(r, "shadelab render: " + junk + ": ")
        with open(self.out, "rb") as f:
            self.assertEqual(f.read(), b"previous image")

    def test_bad_scene(self):
        scene = self.write("bad.json", '{"lights": [{"type": "spot", "cutoff": 120}]}')
        r = run("render", SPOT, "--scene", scene, "-o", self.out)
        self.assertEqual(r.returncode, 1)
        self.assertEqual(r.stderr, "shadelab render: " + scene + ": lights[0].cutoff: 120 is out of range (0, 90]\n")
        self.assertFalse(os.path.exists(self.out))

    def test_missing_texture(self):
        scene = self.write("tex.json", '{"material": {"diffuseTexture": "nowhere.png"}}')
        r = run("render", SPOT, "--scene", scene, "-o", self.out)
        self.assert_one_line_failure(r, "shadelab render: " + os.path.join(self.folder.name, "nowhere.png"))

    def test_usage_errors(self):
        cases = [
            (["render", SPOT], "shadelab render: missing -o/--output FILE\n"),
            (["render", "-o", self.out], "shadelab render: expected one MESH argument, got 0\n"),
            (["render", SPOT, "-o", self.out, "--size", "10x10"],
             'shadelab render: --size: "10x10" is not WxH with 16 <= W, H <= 8192\n'),
            (["render", SPOT, "-o", self.out, "--model", "toon"],
             'shadelab render: --model: "toon" is not a lighting model (' + lighting_models() + ")\n"),
            (["render", SPOT, "-o", self.out, "--bogus"], "shadelab render: unknown option --bogus (see --help)\n"),
        ]
        for args, message in cases:
            r = run(*args)
            self.assertEqual(r.returncode, 2, args)
            self.assertEqual(r.stderr, message)
        self.assertFalse(os.path.exists(self.out))

    def test_unwritable_output(self):
        r = run("render", SPOT, "-o", "/nonexistent-folder/x.png", "-q")
        self.assert_one_line_failure(r, "shadelab render: /nonexistent-folder/x.png: cannot create output file")

    def test_no_display(self):
        env = dict(os.environ)
        env.pop("DISPLAY", None)
        r = subprocess.run([SHADELAB, "render", SPOT, "-o", self.out], capture_output=True, text=True, env=env)
        self.assertEqual(r.returncode, 1)
        self.assertIn("no X display", r.stderr)
        self.assertFalse(os.path.exists(self.out))


class CompareTest(unittest.TestCase):
    def test_frequencies_with_difference_panel(self):
        with tempfile.TemporaryDirectory() as folder:
            out = os.path.join(folder, "compare.png")
            r = run("compare", SPOT, "--diff", "--size", "100x80", "-o", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(png_size(out), (400, 80))
            r = run("compare", SPOT, "--models", "--size", "100x80", "-o", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(png_size(out), (300, 80))

    def test_bad_input(self):
        r = run("compare", "/nonexistent/m.stl", "-o", "/tmp/never.png")
        self.assertEqual(r.returncode, 1)
        self.assertEqual(r.stderr, "shadelab compare: /nonexistent/m.stl: cannot open file\n")
        r = run("compare", SPOT, "-o", "/tmp/never.png", "--amplify", "0")
        self.assertEqual(r.returncode, 2)
        self.assertEqual(r.stderr, "shadelab compare: option --amplify: 0 is out of range [1, 1000]\n")


class LobeImageTest(unittest.TestCase):
    def test_three_part_image(self):
        with tempfile.TemporaryDirectory() as folder:
            image = os.path.join(folder, "lobe.png")
            r = run("lobe", "--models", "phong,blinn-phong", "-o", image)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(png_size(image), (3 * 400, 360))
            r = run("lobe", "--models", "phong,toon", "-o", image + ".other.png")
            self.assertEqual(r.returncode, 2)
            self.assertIn('"toon" is not a lighting model', r.stderr)
            self.assertFalse(os.path.exists(image + ".other.png"))

    def test_lobes_on_a_mesh_image(self):
        with tempfile.TemporaryDirectory() as folder:
            image = os.path.join(folder, "lobes.png")
            r = run("lobe", SPOT, "--points", "8", "-o", image)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(png_size(image), (800, 600))


class FieldImageTest(unittest.TestCase):
    def test_light_and_cosine_images(self):
        with tempfile.TemporaryDirectory() as folder:
            mesh, image = os.path.join(folder, "lit.vtp"), os.path.join(folder, "lit.png")
            r = run("light", SPOT, "-o", mesh, "--image", image)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(png_size(image), (3 * 480, 2 * 360))  # four fields, three per row
            r = run("cosine", SPOT, "-o", mesh, "--image", image, "--fields", "CosThetaRaw_0")
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(png_size(image), (480, 360))

    def test_unknown_field_writes_nothing(self):
        with tempfile.TemporaryDirectory() as folder:
            mesh, image = os.path.join(folder, "lit.vtp"), os.path.join(folder, "lit.png")
            r = run("light", SPOT, "-o", mesh, "--image", image, "--fields", "Radiance,Glow")
            self.assertEqual(r.returncode, 1)
            self.assertEqual(r.stderr, "shadelab light: " + image + ': the mesh has no point or cell array "Glow"\n')
            self.assertEqual(os.listdir(folder), [])


if __name__ == "__main__":
    unittest.main(verbosity=2)
