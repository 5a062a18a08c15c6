"""The shadelab command line: the render job, and one-line errors for bad input."""
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

SHADELAB = os.environ["SHADELAB_EXE"]
DATA = os.environ["SHADELAB_DATA_DIR"]
SPOT = os.path.join(DATA, "meshes", "spot.obj")


def run(*args, cwd=None):
    return subprocess.run([SHADELAB, *args], capture_output=True, text=True, timeout=120, cwd=cwd)


def lighting_models():
    """The lighting models as `shadelab render --help` lists them, from LightingTables.h."""
    text = run("render", "--help").stdout
    return next(line for line in text.splitlines() if "--model NAME" in line).split("lighting model: ", 1)[1].strip()


def png_size(path):
    with open(path, "rb") as f:
        header = f.read(24)
    assert header[:8] == b"\x89PNG\r\n\x1a\n", path
    return int.from_bytes(header[16:20], "big"), int.from_bytes(header[20:24], "big")


def read_ppm(path):
    """(width, height, rows): a binary PPM (P6, maxval 255) as rows, top first, of (r, g, b)."""
    with open(path, "rb") as f:
        data = f.read()
    fields, at = [], 0
    while len(fields) < 4:  # magic, width, height, maxval, with blanks between
        while data[at:at + 1].isspace():
            at += 1
        end = at
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[at:end])
        at = end
    assert fields[0] == b"P6" and fields[3] == b"255", path
    width, height = int(fields[1]), int(fields[2])
    pixels = data[at + 1:]
    rows = [[tuple(pixels[3 * (y * width + x):3 * (y * width + x) + 3]) for x in range(width)] for y in range(height)]
    return width, height, rows


def many_lights_scene(folder, count):
    """A scene file with @count dim directional lights."""
    path = os.path.join(folder, "lights%d.json" % count)
    with open(path, "w") as f:
        json.dump({"lights": [{"type": "directional", "direction": [0, -0.3 * (i % 3), -1], "intensity": 0.05}
                              for i in range(count)]}, f)
    return path


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

    def test_vtk_lighting_notes_what_it_cannot_show(self):
        # One note per item the scene holds and VTK's lighting lacks, from the
        # material (emission, model, frequency) and from the lights alike.
        scene = self.write("s.json", json.dumps({
            "shading": {"model": "blinn-phong-normalized", "frequency": "gouraud"},
            "material": {"emission": [0.2, 0.1, 0.0]},
            "lights": [{"type": "spot", "position": [0, 0, 5], "direction": [0, 0, -1], "cutoff": 30, "edge": 5}]}))
        r = run("render", SPOT, "--scene", scene, "--size", "64x48", "--vtk-lighting", "-o", self.out)
        self.assertEqual(r.returncode, 0, r.stderr)
        notes = [line for line in r.stderr.splitlines() if line.startswith("shadelab render: note: ")]
        for item in ("material.emission", "shading.frequency", "shading.model", "lights[0].edge"):
            self.assertEqual(sum(item in line for line in notes), 1, (item, r.stderr))
        quiet = run("render", SPOT, "--scene", scene, "--size", "64x48", "--vtk-lighting", "-q", "-o", self.out)
        self.assertEqual((quiet.returncode, quiet.stderr), (0, ""))

    def test_builtin_scene_size_and_formats(self):
        for mesh in ("fandisk.obj", "teapot.obj"):
            r = run("render", os.path.join(DATA, "meshes", mesh), "--size", "64x48", "-o", self.out)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(png_size(self.out), (64, 48))

    def test_missing_mesh(self):
        r = run("render", "/nonexistent/cow.obj", "-o", self.out)
        self.assertEqual(r.returncode, 1)
        self.assertEqual(r.stderr, "shadelab render: /nonexistent/cow.obj: cannot open file: No such file or directory\n")
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

    def test_brdf_in_scene(self):
        # brdf.file is resolved beside the scene file, --brdf beside the working directory.
        with open(os.path.join(DATA, "brdf", "blinn-phong-normalized.brdf")) as f:
            self.write("glossy.brdf", f.read())
        scene = self.write("s.json", '{"imageSize": [96, 72], "brdf": {"file": "glossy.brdf", "parameters": {"ks": 0}}, '
                           '"lights": [{"type": "directional", "space": "camera", "intensity": 3}]}')
        images = {}
        for name, args in (("scene", []), ("param", ["--param", "ks=0.9"]),
                           ("option", ["--brdf", os.path.join(DATA, "brdf", "blinn-phong-normalized.brdf"),
                                       "--param", "ks=0"])):
            out = os.path.join(self.folder.name, name + ".png")
            r = subprocess.run([SHADELAB, "render", SPOT, "--scene", "s.json", "-o", out, *args], capture_output=True,
                               text=True, timeout=120, cwd=self.folder.name)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(out, "rb") as f:
                images[name] = f.read()
        self.assertEqual(images["scene"], images["option"], "the same file and value, two ways")
        self.assertNotEqual(images["scene"], images["param"], "--param sets a value over the scene's")

        bad = self.write("bad.json", '{"brdf": {"file": "glossy.brdf", "parameters": {"ks": 2}}}')
        r = run("render", SPOT, "--scene", bad, "-o", self.out)
        self.assert_one_line_failure(r, "shadelab render: " + os.path.join(self.folder.name, "glossy.brdf") + ": ")
        self.assertIn("ks 2 is out of range [0, 1]", r.stderr)
        self.assertFalse(os.path.exists(self.out))

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

    def test_options_the_image_would_ignore(self):
        # Each was accepted and gave the same image as without it.
        with open(self.out, "wb") as f:
            f.write(b"previous image")
        cases = [
            (["--vtk-lighting", "--component", "specular", "--false-color"],
             "--component: only for ShadeLab's pass, not with --vtk-lighting"),
            (["--vtk-lighting", "--false-color"], "--false-color: only for ShadeLab's pass, not with --vtk-lighting"),
            (["--light", "1"], "--light: only with --component ambient, diffuse, specular or cos"),
            (["--component", "emission", "--light", "0"], "--light: only with --component ambient, diffuse, specular or cos"),
            (["--component", "total", "--light", "0"], "--light: only with --component ambient, diffuse, specular or cos"),
            (["--false-color"], "--false-color: only with --component ambient, diffuse, specular, emission or cos"),
            (["--component", "total", "--false-color"],
             "--false-color: only with --component ambient, diffuse, specular, emission or cos"),
        ]
        for args, message in cases:
            r = run("render", SPOT, *args, "-o", self.out)
            self.assertEqual((r.returncode, r.stderr), (2, "shadelab render: " + message + "\n"), args)
        with open(self.out, "rb") as f:
            self.assertEqual(f.read(), b"previous image")

    def test_light_index_exit_status(self):
        # No scene has light -1 or 16 in the pass: a usage error (2). Whether
        # light 9 exists only the scene can tell: exit 1, as cosine and lobe.
        for k, status in (("-1", 2), ("16", 2), ("9", 1)):
            r = run("render", SPOT, "--component", "cos", "--light", k, "-o", self.out)
            self.assertEqual(r.returncode, status, r.stderr)
            self.assertEqual(r.stderr.count("\n"), 1, r.stderr)
            self.assertTrue(r.stderr.startswith("shadelab render: --light: "), r.stderr)
        self.assertFalse(os.path.exists(self.out))

    def test_more_lights_than_the_pass_holds(self):
        # The pass drew the first 16 of 17 and said nothing; the CPU filters use all 17.
        scene = many_lights_scene(self.folder.name, 17)
        r = run("render", SPOT, "--scene", scene, "--size", "32x32", "-o", self.out)
        self.assertEqual((r.returncode, r.stderr),
                         (1, "shadelab render: " + scene + ": 17 lights; ShadeLab's lighting pass draws at most 16\n"))
        self.assertFalse(os.path.exists(self.out))
        # VTK's own lighting takes them all; 16 is the pass's limit.
        r = run("render", SPOT, "--scene", scene, "--size", "32x32", "--vtk-lighting", "-q", "-o", self.out)
        self.assertEqual((r.returncode, r.stderr), (0, ""))
        r = run("render", SPOT, "--scene", many_lights_scene(self.folder.name, 16), "--size", "32x32", "-o", self.out)
        self.assertEqual((r.returncode, r.stderr), (0, ""))

    def test_pass_reports_dropped_lights_as_an_error(self):
        # A library user's slLightingPass draws the first 16 of 17 lights and
        # says so with an ErrorEvent (it was a warning the app swallowed).
        scene = many_lights_scene(self.folder.name, 17)
        script = """
import sys, shadelab
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkFiltersSources import vtkSphereSource
scene = shadelab.slScene()
assert scene.ReadFile(sys.argv[1])
sphere = vtkSphereSource()
sphere.Update()
renderer = shadelab.slSceneRenderer()
renderer.SetScene(scene)
renderer.SetMesh(sphere.GetOutput())
renderer.SetWidth(32)
renderer.SetHeight(32)
errors = []
@calldata_type(VTK_STRING)
def keep(caller, event, text):
    errors.append(text.strip().splitlines()[-1].partition("): ")[2])
renderer.GetLightingPass().AddObserver("ErrorEvent", keep)
renderer.Render()
print(renderer.GetLightingPass().GetNumberOfLightsUsed())
print("|".join(errors))
"""
        r = subprocess.run([sys.executable, "-c", script, scene], capture_output=True, text=True, timeout=120)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout.splitlines(), [
            "16", "17 lights; ShadeLab's lighting pass draws at most 16: the others are left out of the picture"])

    def test_capture_beyond_the_largest_image_fails_loudly(self):
        # Three lobe-image panels of 8192 (the largest panel) make a window
        # OpenGL cannot draw: the capture names the problem instead of
        # returning black, as an ErrorEvent, and Render() fails; the process
        # goes on (a field image and a scene render alike).
        script = """
import shadelab
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
r = shadelab.slLobeImageRenderer()
r.AddModel("phong")
r.SetPanelWidth(8192)
r.SetPanelHeight(16)
@calldata_type(VTK_STRING)
def keep(caller, event, text):
    print(text)
r.AddObserver("ErrorEvent", keep)
print(r.GetPanelWidth(), r.Render(), r.GetImage() is None)
"""
        r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("24576x16 pixels is beyond the largest image this OpenGL can render, 16384x16384", r.stdout)
        self.assertIn("8192 False", r.stdout)

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
    def test_difference_of_the_last_two_panels(self):
        # As --help and docs/render-pass.md say: |panel n-1 - panel n|, here
        # two identical Lambert panels, so the difference panel is black
        # below its label (it showed |blinn-phong - lambert|, panels 2 and 3).
        with tempfile.TemporaryDirectory() as folder:
            out = os.path.join(folder, "grid.ppm")
            r = run("compare", SPOT, "--grid", "phong,blinn-phong,lambert,lambert", "--diff", "--amplify", "1",
                    "--columns", "5", "--size", "64x48", "-o", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            width, height, rows = read_ppm(out)
            self.assertEqual((width, height), (5 * 64, 48))
            below_label = [max(p) for row in rows[height // 3:] for p in row[4 * 64:]]
            self.assertLessEqual(max(below_label), 2)
            lambert = [max(p) for row in rows[height // 3:] for p in row[3 * 64:4 * 64]]
            self.assertGreater(max(lambert), 50, "the panels are drawn")
            # Two panels are enough (it failed: "difference panels 1 and 2 do not exist").
            r = run("compare", SPOT, "--grid", "phong,blinn-phong", "--diff", "--size", "64x48", "-o", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(read_ppm(out)[:2], (3 * 64, 48))
            r = run("compare", SPOT, "--grid", "phong", "--diff", "-o", os.path.join(folder, "one.png"))
            self.assertEqual((r.returncode, r.stderr),
                             (2, "shadelab compare: --diff: needs two panels to compare (--grid names 1)\n"))
            self.assertFalse(os.path.exists(os.path.join(folder, "one.png")))

    def test_composite_beyond_the_largest_image_is_refused(self):
        # It wrote a black 20000x64 image, and clamped 6000-wide panels to
        # 4096 (a 12288x200 image): refused before any work now.
        five = "lambert,phong,blinn-phong,lambert-normalized,phong-normalized"
        with tempfile.TemporaryDirectory() as folder:
            out = os.path.join(folder, "big.png")
            for args, message in (
                    (["--grid", five, "--columns", "5", "--size", "4000x64"],
                     "5 panels of 4000x64, 5 a row, make a 20000x64 image"),
                    (["--grid", five, "--columns", "1", "--size", "200x4000"],
                     "5 panels of 200x4000, 1 a row, make a 200x20000 image"),
                    (["--size", "6000x200"], "3 panels of 6000x200, 3 a row, make a 18000x200 image")):
                r = run("compare", "/nonexistent/m.obj", *args, "-o", out)  # refused before the mesh is read
                self.assertEqual((r.returncode, r.stderr), (2, "shadelab compare: --size: " + message +
                                                            "; at most 16384x16384 can be rendered\n"), args)
                self.assertFalse(os.path.exists(out))
            # Panels wider than 4096 are honoured when the composite fits.
            r = run("compare", SPOT, "--size", "5000x16", "-o", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(png_size(out), (15000, 16))

    def test_options_the_image_would_ignore(self):
        with tempfile.TemporaryDirectory() as folder:
            out = os.path.join(folder, "a.png")
            r = run("compare", SPOT, "--amplify", "2", "-o", out)
            self.assertEqual((r.returncode, r.stderr), (2, "shadelab compare: --amplify: only with --diff\n"))
            self.assertFalse(os.path.exists(out))

    def test_more_lights_than_the_pass_holds(self):
        with tempfile.TemporaryDirectory() as folder:
            scene = many_lights_scene(folder, 17)
            out = os.path.join(folder, "c.png")
            r = run("compare", SPOT, "--scene", scene, "--size", "32x32", "-o", out)
            self.assertEqual((r.returncode, r.stderr), (1, "shadelab compare: " + scene +
                                                        ": 17 lights; ShadeLab's lighting pass draws at most 16\n"))
            self.assertFalse(os.path.exists(out))

    def test_frequencies_with_difference_panel(self):
        with tempfile.TemporaryDirectory() as folder:
            out = os.path.join(folder, "compare.png")
            r = run("compare", SPOT, "--diff", "--size", "100x80", "-o", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(png_size(out), (400, 80))
            r = run("compare", SPOT, "--models", "--size", "100x80", "-o", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(png_size(out), (300, 80))

    def test_grid_of_models(self):
        with tempfile.TemporaryDirectory() as folder:
            out = os.path.join(folder, "grid.png")
            r = run("compare", SPOT, "--grid", "lambert,phong,cook-torrance-ggx,oren-nayar,blinn-phong",
                    "--columns", "2", "--size", "100x80", "-o", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(png_size(out), (200, 240))  # 5 panels, 2 a row: 3 rows
            spot = os.path.join(folder, "spot.vtp")
            self.assertEqual(run("tangents", SPOT, "-o", spot).returncode, 0)
            r = run("compare", spot, "--grid", "all", "--size", "100x80", "-o", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            rows = (len(lighting_models().split(", ")) + 3) // 4
            self.assertEqual(png_size(out), (400, 80 * rows))

    def test_grid_bad_input(self):
        out = "/tmp/never.png"
        r = run("compare", SPOT, "--grid", "phong,glossy", "-o", out)
        self.assertEqual(r.returncode, 2)
        self.assertRegex(r.stderr, r'^shadelab compare: --grid: "glossy" is not a lighting model \(lambert, .*\)\n$')
        r = run("compare", SPOT, "--grid", "phong", "--models", "-o", out)
        self.assertEqual((r.returncode, r.stderr), (2, "shadelab compare: --grid: give either --grid or --models\n"))
        r = run("compare", SPOT, "--grid", "phong,ward", "-o", out)
        self.assertEqual(r.returncode, 1)
        self.assertIn("the ward model is anisotropic and needs tangents", r.stderr)
        r = run("compare", SPOT, "--grid", "phong", "--columns", "0", "-o", out)
        self.assertEqual((r.returncode, r.stderr), (2, "shadelab compare: --columns: 0 is out of range [1, 64]\n"))
        self.assertFalse(os.path.exists(out))

    def test_bad_input(self):
        r = run("compare", "/nonexistent/m.stl", "-o", "/tmp/never.png")
        self.assertEqual(r.returncode, 1)
        self.assertEqual(r.stderr, "shadelab compare: /nonexistent/m.stl: cannot open file: No such file or directory\n")
        r = run("compare", SPOT, "-o", "/tmp/never.png", "--amplify", "0")
        self.assertEqual(r.returncode, 2)
        self.assertEqual(r.stderr, "shadelab compare: --amplify: 0 is out of range [1, 1000]\n")


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

    def test_brdf_files_overlaid_with_their_albedo(self):
        bp = os.path.join(DATA, "brdf", "blinn-phong-normalized.brdf")
        ward = os.path.join(DATA, "brdf", "ward-anisotropic.brdf")
        with tempfile.TemporaryDirectory() as folder:
            image = os.path.join(folder, "lobe.png")
            r = run("lobe", "--models", "phong", "--brdf", bp, "--param", "kd=0", "--param", "ks=1", "--brdf", ward,
                    "--incidence", "0", "-o", image)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(png_size(image), (3 * 400, 360))
            lines = r.stdout.splitlines()
            # Normalised Blinn-Phong reflects exactly 1 at normal incidence.
            self.assertTrue(lines[0].startswith("albedo of blinn-phong-normalized.brdf at 0 degrees: "), lines)
            self.assertAlmostEqual(float(lines[0].rsplit(" ", 1)[1]), 1.0, delta=1e-4)
            self.assertTrue(lines[1].startswith("albedo of ward-anisotropic.brdf at 0 degrees: "), lines)
            # The albedo table takes a column per file; a lobe mesh takes one file.
            table = os.path.join(folder, "albedo.csv")
            r = run("lobe", "--albedo-table", "--brdf", bp, "--param", "kd=0", "--param", "ks=1", "--brdf", bp,
                    "-o", table)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(table) as f:
                header, first = f.readline().strip().split(","), f.readline().strip().split(",")
            self.assertEqual(header[-2:], ["blinn-phong-normalized.brdf", "blinn-phong-normalized.brdf (2)"])
            self.assertAlmostEqual(float(first[-2]), 1.0, delta=1e-4)
            self.assertAlmostEqual(float(first[-1]), 1.0, delta=1e-4)  # kd 0.5 + ks 0.5, both reflect 1
            r = run("lobe", "--brdf", bp, "--brdf", ward, "-o", os.path.join(folder, "lobe.vtp"))
            self.assertEqual(r.returncode, 2)
            self.assertEqual(r.stderr, "shadelab lobe: --brdf: a lobe mesh takes one .brdf file; an image (-o LOBE.png) "
                                       "overlays several\n")

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


def point_array(path, name):
    import vtk
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    array = reader.GetOutput().GetPointData().GetArray(name)
    return [array.GetTuple(i) for i in range(array.GetNumberOfTuples())]


class MaterialOptionsTest(unittest.TestCase):
    """The material's numbers on the command line (one option per number row of the material table)."""

    def test_every_subcommand_that_lights_lists_them(self):
        for command in ("render", "light", "lobe", "reference"):
            text = run(command, "--help").stdout
            for option in ("--shininess X", "--roughness X", "--roughness-x X", "--roughness-y X", "--ior X"):
                self.assertIn(option, text, command)
        self.assertNotIn("--roughness", run("cosine", "--help").stdout)  # N.L reads no material

    def test_options_equal_the_scene_keys(self):
        with tempfile.TemporaryDirectory() as folder:
            with open(os.path.join(DATA, "scenes", "default.json")) as f:
                scene = json.load(f)
            scene["shading"]["model"] = "cook-torrance-ggx"
            scene["material"].update(roughness=0.2, ior=3.0)
            scene["material"].pop("diffuseTexture")
            path, by_file, by_option = (os.path.join(folder, n) for n in ("s.json", "file.vtp", "option.vtp"))
            with open(path, "w") as f:
                json.dump(scene, f)
            r = run("light", SPOT, "--scene", path, "-o", by_file)
            self.assertEqual(r.returncode, 0, r.stderr)
            scene["material"].update(roughness=0.3, ior=1.5)  # the defaults: the options set them
            with open(path, "w") as f:
                json.dump(scene, f)
            r = run("light", SPOT, "--scene", path, "--roughness", "0.2", "--ior", "3", "-o", by_option)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(point_array(by_option, "Radiance"), point_array(by_file, "Radiance"))
            r = run("light", SPOT, "--scene", path, "-o", by_option)
            self.assertNotEqual(point_array(by_option, "Radiance"), point_array(by_file, "Radiance"))

    def test_lone_ward_lobe_peak(self):
        """Ward with L = V = N: f_r = 1 / (4 pi ax ay)."""
        with tempfile.TemporaryDirectory() as folder:
            lobe = os.path.join(folder, "lobe.vtp")
            r = run("lobe", "--model", "ward", "--incidence", "0", "--roughness-x", "0.2", "--roughness-y", "0.5",
                    "-o", lobe)
            self.assertEqual(r.returncode, 0, r.stderr)
            peak = max(v[0] for v in point_array(lobe, "BRDF"))
            self.assertAlmostEqual(peak * 4.0 * math.pi * 0.2 * 0.5, 1.0, delta=1e-4)


def address_sanitized():
    """Whether SHADELAB is built with AddressSanitizer, which reserves terabytes
    of address space up front: an address-space limit makes it abort."""
    return "libasan" in subprocess.run(["ldd", SHADELAB], capture_output=True, text=True).stdout


def limited_run(*args, cwd=None):
    """run() with at most 3 GB of address space and 60 s: a reader that never stops fails, not the machine."""
    import resource

    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (3 << 30, 3 << 30))
    assert not address_sanitized(), "no address-space limit under AddressSanitizer"
    return subprocess.run([SHADELAB, *args], capture_output=True, text=True, timeout=60, preexec_fn=limit, cwd=cwd)


class SpecialFilesTest(unittest.TestCase):
    """Every input must be a regular file: a device reads for ever, a FIFO blocks."""

    def test_devices_and_fifos_are_refused(self):
        with tempfile.TemporaryDirectory() as folder:
            with open(os.path.join(folder, "t.obj"), "w") as f:
                f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
            for name in ("z.obj", "z.png"):
                os.symlink("/dev/zero", os.path.join(folder, name))
            os.mkfifo(os.path.join(folder, "s.json"))
            before = sorted(os.listdir(folder))
            # Under AddressSanitizer no memory limit can guard a reader of
            # /dev/zero that the check lets through: the FIFO alone (a
            # timeout guards it) is tried there.
            sanitized = address_sanitized()
            cases = [(["cosine", "t.obj", "--scene", "s.json"], "s.json")]
            if not sanitized:
                cases += [(["normals", "z.obj"], "z.obj"), (["light", "t.obj", "--diffuse-texture", "z.png"], "z.png"),
                          (["cosine", "t.obj", "--scene", "/dev/zero"], "/dev/zero")]
            for args, path in cases:
                r = (run(*args, "-o", "out.vtp", cwd=folder) if sanitized
                     else limited_run(*args, "-o", "out.vtp", cwd=folder))
                self.assertEqual(r.returncode, 1, args)
                self.assertEqual(r.stderr, "shadelab %s: %s: is not a regular file (a device, pipe or socket)\n"
                                 % (args[0], path))
                self.assertEqual(sorted(os.listdir(folder)), before, "nothing written")


class LobeOptionsTest(unittest.TestCase):
    def test_field_image_options_are_not_offered(self):
        # lobe draws its own images (-o LOBE.png); --image and --fields are the lit meshes' of cosine, light, reference.
        self.assertNotIn("--image", run("lobe", "--help").stdout)
        self.assertNotIn("--fields", run("lobe", "--help").stdout)
        self.assertIn("--image", run("cosine", "--help").stdout)


def read_vtp(path):
    import vtk
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def cells(mesh, cell_type):
    """The point ids of each cell of @cell_type (a VTK cell type number) in @mesh."""
    import vtk
    ids = vtk.vtkIdList()
    out = []
    for c in range(mesh.GetNumberOfCells()):
        if mesh.GetCellType(c) == cell_type:
            mesh.GetCellPoints(c, ids)
            out.append([ids.GetId(k) for k in range(ids.GetNumberOfIds())])
    return out


class OBJElementsTest(unittest.TestCase):
    """OBJ faces beside l and p elements, and faces with and without vn, as `shadelab normals` reads them."""
    TRIANGLE, LINE, VERTEX = 5, 3, 1

    def face_normal(self, mesh, polygon):
        (ax, ay, az), (bx, by, bz), (cx, cy, cz) = (mesh.GetPoint(i) for i in polygon[:3])
        u, v = (bx - ax, by - ay, bz - az), (cx - ax, cy - ay, cz - az)
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        length = math.sqrt(sum(x * x for x in n))
        return tuple(x / length for x in n)

    def normals(self, text):
        with tempfile.TemporaryDirectory() as folder:
            path, out = os.path.join(folder, "m.obj"), os.path.join(folder, "m.vtp")
            with open(path, "w") as f:
                f.write(text)
            r = run("normals", path, "-o", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            return read_vtp(out)

    def assert_flat_faces(self, mesh):
        """Every triangle's points carry its own face normal (sharp edges are split)."""
        normals = mesh.GetPointData().GetNormals()
        for polygon in cells(mesh, self.TRIANGLE):
            for i in polygon:
                for got, want in zip(normals.GetTuple(i), self.face_normal(mesh, polygon)):
                    self.assertAlmostEqual(got, want, places=6)

    def test_faces_with_lines_and_points(self):
        mesh = self.normals("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1 2\np 3\n")
        self.assertEqual(mesh.GetNumberOfPoints(), 3)
        self.assertEqual(cells(mesh, self.TRIANGLE), [[0, 1, 2]])
        self.assertEqual(cells(mesh, self.LINE), [[0, 1]])
        self.assertEqual(cells(mesh, self.VERTEX), [[2]])
        self.assertEqual(self.face_normal(mesh, [0, 1, 2]), (0.0, 0.0, 1.0))
        self.assert_flat_faces(mesh)

    def test_faces_with_and_without_normals(self):
        # Both faces are read; the file's vn covers only the first, so the normals are computed.
        mesh = self.normals("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1 2 4\n")
        triangles = cells(mesh, self.TRIANGLE)
        self.assertEqual(len(triangles), 2)
        corners = sorted(sorted(mesh.GetPoint(i) for i in t) for t in triangles)
        self.assertEqual(corners, [[(0, 0, 0), (0, 0, 1), (1, 0, 0)], [(0, 0, 0), (0, 1, 0), (1, 0, 0)]])
        # The triangles meet at a right angle: (0, 0, 1) and, oriented alike across their shared edge, (0, 1, 0).
        self.assertEqual(sorted(self.face_normal(mesh, t) for t in triangles), [(0.0, 0.0, 1.0), (0.0, 1.0, 0.0)])
        self.assert_flat_faces(mesh)


if __name__ == "__main__":
    unittest.main(verbosity=2)
