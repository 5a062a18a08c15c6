"""shadelab cosine / light / lobe / reference: help, outputs, one-line errors."""
import math
import os
import struct
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

    def test_scene_help_describes_the_built_in_scene(self):
        # The built-in scene's lights, as cosine writes one CosTheta_<i> per light: key, fill, ambient.
        r = run("cosine", SPOT, "--no-cells", "-o", self.out("c.vtk"))
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(self.out("c.vtk"), "rb") as f:
            text = f.read()
        self.assertEqual([text.count(b"CosThetaRaw_%d " % i) for i in range(4)], [1, 1, 1, 0])
        for command in ("render", "compare", "cosine", "light", "reference"):
            help_text = run(command, "--help").stdout
            self.assertIn("built-in scene: key and fill lights in camera space, and an ambient light", help_text,
                          command)

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

    def test_albedo_table_of_chosen_models_and_angles(self):
        """--models and --model choose the columns (in the table's order), --angles the rows
        (0 to 89 degrees); lecture Phong's albedo at normal incidence is 2 pi / (n + 2)."""
        r = run("lobe", "--albedo-table", "--models", "ward,phong", "--angles", "4", "--shininess", "30",
                "-o", self.out("two.csv"))
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(self.out("two.csv")) as f:
            rows = [line.strip().split(",") for line in f]
        self.assertEqual(rows[0], ["IncidenceDegrees", "phong", "ward"])
        for row, degrees in zip(rows[1:], [0.0, 89.0 / 3, 2 * 89.0 / 3, 89.0], strict=True):
            self.assertAlmostEqual(float(row[0]), degrees, places=8)
        # Written with 10 significant digits, integrated to 1e-9 relative.
        self.assertAlmostEqual(float(rows[1][1]), 2 * math.pi / 32, places=8)
        r = run("lobe", "--albedo-table", "--model", "oren-nayar", "--roughness", "0", "-o", self.out("one.csv"))
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(self.out("one.csv")) as f:
            rows = [line.strip().split(",") for line in f]
        self.assertEqual(rows[0], ["IncidenceDegrees", "oren-nayar"])
        self.assertEqual(len(rows), 11)
        # Oren-Nayar at roughness 0 is the normalised Lambert: 1 at every angle, but for
        # its 1 / pi, which slLighting.glsl takes from pi rounded to float.
        float_pi = struct.unpack("f", struct.pack("f", math.pi))[0]
        for row in rows[1:]:
            self.assertAlmostEqual(float(row[1]), math.pi / float_pi, places=9)

    def test_scene_diffuse_texture_multiplies_k_d(self):
        """material.diffuseTexture is the base colour of light's Diffuse, as render draws it: k_d * texel * N.L."""
        import vtk
        from vtk.util.numpy_support import vtk_to_numpy
        image = vtk.vtkImageData()
        image.SetDimensions(2, 2, 1)
        image.AllocateScalars(vtk.VTK_UNSIGNED_CHAR, 3)
        for i in range(4):
            image.GetPointData().GetScalars().SetTuple3(i, 51, 102, 204)  # 0.2, 0.4, 0.8
        writer = vtk.vtkPNGWriter()
        writer.SetInputData(image)
        writer.SetFileName(self.out("t.png"))
        writer.Write()
        quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
        with open(self.out("uv.obj"), "w") as f:
            f.write(quad + "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n")
        with open(self.out("plain.obj"), "w") as f:
            f.write(quad + "f 1 2 3 4\n")
        with open(self.out("s.json"), "w") as f:
            f.write('{"shading": {"model": "lambert"}, "material": {"ambient": [0, 0, 0], "diffuse": [0.5, 0.5, 0.5], '
                    '"specular": [0, 0, 0], "diffuseTexture": "t.png"}, '
                    '"lights": [{"type": "directional", "direction": [0, -1, -1]}]}')
        cos = 0.5 ** 0.5  # N = +z, L = (0, 1, 1) / sqrt(2)
        # A mesh without texture coordinates render draws untextured: k_d alone.
        for mesh, texel in (("uv.obj", (0.2, 0.4, 0.8)), ("plain.obj", (1.0, 1.0, 1.0))):
            r = run("light", self.out(mesh), "--scene", self.out("s.json"), "-o", self.out("l.vtp"))
            self.assertEqual(r.returncode, 0, r.stderr)
            reader = vtk.vtkXMLPolyDataReader()
            reader.SetFileName(self.out("l.vtp"))
            reader.Update()
            diffuse = vtk_to_numpy(reader.GetOutput().GetPointData().GetArray("Diffuse"))
            self.assertEqual(diffuse.shape, (4, 3))
            for point in diffuse:
                for value, t in zip(point, texel):
                    self.assertAlmostEqual(value, 0.5 * t * cos, places=5, msg=mesh)

    # A plane under a small sun for comparing reference with light: a 5 x 2 grid on z = 0 with u = x, and a 2 x 2
    # texture whose left column is red and right column blue, so that u = 0.25 is the red texels' centre, 0.75 the
    # blue's and the points in between mix them (bilinear, repeat wrapping).
    RED, BLUE = (0.8, 0.2, 0.2), (0.2, 0.2, 0.8)
    K_D, INTENSITY, SUN = 0.9, 2.0, (0.3, 0.2, -1.0)
    XS, YS = (0, 0.25, 0.5, 0.75, 1), (0, 1)
    QUADS = [(i + 1, i + 2, i + 7, i + 6) for i in range(4)]

    def write_textured_plane(self):
        """t.png; uv.obj and plain.obj (the grid with and without texture coordinates); s.json (the sun, Lambert,
        k_d = K_D, material.diffuseTexture t.png) and plain.json (the same without the texture)."""
        import vtk
        image = vtk.vtkImageData()
        image.SetDimensions(2, 2, 1)
        image.AllocateScalars(vtk.VTK_UNSIGNED_CHAR, 3)
        for i in range(4):
            image.GetPointData().GetScalars().SetTuple3(
                i, *(round(255 * c) for c in (self.RED if i % 2 == 0 else self.BLUE)))
        writer = vtk.vtkPNGWriter()
        writer.SetInputData(image)
        writer.SetFileName(self.out("t.png"))
        writer.Write()
        vertices = "".join("v %g %g 0\n" % (x, y) for y in self.YS for x in self.XS)
        with open(self.out("uv.obj"), "w") as f:
            f.write(vertices + "".join("vt %g %g\n" % (x, y) for y in self.YS for x in self.XS) +
                    "".join("f {0}/{0} {1}/{1} {2}/{2} {3}/{3}\n".format(*q) for q in self.QUADS))
        with open(self.out("plain.obj"), "w") as f:
            f.write(vertices + "".join("f %d %d %d %d\n" % q for q in self.QUADS))
        for name, texture in (("s.json", ', "diffuseTexture": "t.png"'), ("plain.json", "")):
            with open(self.out(name), "w") as f:
                f.write('{"shading": {"model": "lambert-normalized"}, "material": {"ambient": [0, 0, 0], '
                        '"diffuse": [%g, %g, %g], "specular": [0, 0, 0]%s}, '
                        '"lights": [{"type": "directional", "intensity": %g, "direction": [%g, %g, %g]}]}'
                        % (self.K_D, self.K_D, self.K_D, texture, self.INTENSITY, *self.SUN))

    def sun_cos(self):
        return 1.0 / math.sqrt(sum(c * c for c in self.SUN))  # N = +z

    def lit_arrays(self, command, mesh, scene, *options):
        """Radiance (and RadianceStdError) of @command on @mesh under @scene; reference samples the small sun."""
        import vtk
        from vtk.util.numpy_support import vtk_to_numpy
        if command == "reference":
            options += ("--sampling", "light", "--sun-angle", "0.25", "--samples", "64")
        r = run(command, self.out(mesh), "--scene", self.out(scene), *options, "-o", self.out("r.vtp"))
        self.assertEqual(r.returncode, 0, r.stderr)
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(self.out("r.vtp"))
        reader.Update()
        data = reader.GetOutput().GetPointData()
        return {name: vtk_to_numpy(data.GetArray(name)) for name in ("Radiance", "RadianceStdError")
                if data.GetArray(name) is not None}

    def assert_reference_is_light(self, mesh, scene, *options):
        """reference's Radiance is light's within 0.5 % + 5 sigma at every point, with the same @options; returns
        reference's arrays."""
        light = self.lit_arrays("light", mesh, scene, *options)["Radiance"]
        reference = self.lit_arrays("reference", mesh, scene, *options)
        self.assertEqual(light.shape, (10, 3))
        for point, (l, r, sigma) in enumerate(zip(light, reference["Radiance"], reference["RadianceStdError"])):
            for c in range(3):
                self.assertLessEqual(abs(r[c] - l[c]), 0.005 * l[c] + 5 * sigma[c] + 1e-6,
                                     (mesh, options, point, c, list(r), list(l)))
        return reference

    def assert_base_colour_at(self, reference, point, base):
        """reference's Radiance at @point is k_d * @base * I cos / pi within 0.5 % + 5 sigma."""
        r, sigma = reference["Radiance"][point], reference["RadianceStdError"][point]
        for c in range(3):
            value = self.K_D * base[c] * self.INTENSITY * self.sun_cos() / math.pi
            self.assertLessEqual(abs(r[c] - value), 0.005 * value + 5 * sigma[c], (point, c, list(r), value))

    def test_reference_applies_the_scene_diffuse_texture_as_light_does(self):
        """reference colours k_d with material.diffuseTexture as light does: a textured plane under a small sun has
        light's Radiance within the reference's own error, a point at the centre of the red texels is
        k_d * red * I cos / pi, and a mesh without texture coordinates stays untextured in both."""
        self.write_textured_plane()
        for mesh in ("uv.obj", "plain.obj"):
            reference = self.assert_reference_is_light(mesh, "s.json")
            # The red texels' centre (u = 0.25): the analytic value, red-dominated; without UVs, untextured.
            expected = self.RED if mesh == "uv.obj" else (1.0, 1.0, 1.0)
            for point in (1, 6):
                self.assert_base_colour_at(reference, point, expected)
                if mesh == "uv.obj":
                    r = reference["Radiance"][point]
                    self.assertGreater(r[0], 3 * max(r[1], r[2]), list(r))
            if mesh == "uv.obj":
                self.assertGreater(reference["Radiance"][3][2], 3 * reference["Radiance"][3][0])  # blue at u = 0.75

    def test_reference_takes_diffuse_array_and_texture_as_light_does(self):
        """reference takes --diffuse-texture FILE and --diffuse-array NAME as light does: the same Radiance within
        the reference's own error at every point, and k_d * base colour * I cos / pi where the base colour is known.
        Each option replaces the scene's texture (plain.json has none; s.json's is not read for the array)."""
        import vtk
        self.write_textured_plane()
        reference = self.assert_reference_is_light("uv.obj", "plain.json", "--diffuse-texture", self.out("t.png"))
        for point in (1, 6):
            self.assert_base_colour_at(reference, point, self.RED)
        for point in (3, 8):
            self.assert_base_colour_at(reference, point, self.BLUE)

        # The grid as VTP with a per-point RGB array that changes along x.
        base = [(0.2 + 0.6 * x, 0.8 - 0.6 * x, 0.5) for y in self.YS for x in self.XS]
        points, colours, polys = vtk.vtkPoints(), vtk.vtkFloatArray(), vtk.vtkCellArray()
        colours.SetName("Base")
        colours.SetNumberOfComponents(3)
        for y in self.YS:
            for x in self.XS:
                points.InsertNextPoint(x, y, 0)
        for b in base:
            colours.InsertNextTuple3(*b)
        for q in self.QUADS:
            polys.InsertNextCell(4, [i - 1 for i in q])
        grid = vtk.vtkPolyData()
        grid.SetPoints(points)
        grid.SetPolys(polys)
        grid.GetPointData().AddArray(colours)
        writer = vtk.vtkXMLPolyDataWriter()
        writer.SetInputData(grid)
        writer.SetFileName(self.out("base.vtp"))
        self.assertEqual(writer.Write(), 1)
        reference = self.assert_reference_is_light("base.vtp", "s.json", "--diffuse-array", "Base")
        for point in range(10):
            self.assert_base_colour_at(reference, point, base[point])

    def test_lobe_at_grazing_incidence(self):
        """Built-in models have f_r = 0 at 90 degrees (slBRDF's grazing limit): refused, not an empty lobe."""
        import vtk
        from vtk.util.numpy_support import vtk_to_numpy
        for args in (["--model", "lambert-normalized"], ["--models", "phong,ward"]):
            target = self.out("x.png" if "--models" in args else "x.vtp")
            r = run("lobe", *args, "--incidence", "90", "-o", target)
            self.assertEqual(r.returncode, 2, (args, r.stderr))
            self.assertEqual(r.stderr.count("\n"), 1, r.stderr)
            self.assertIn("--incidence 90: the light grazes the surface", r.stderr)
            self.assertFalse(os.path.exists(target), args)
        # Just below: normalised Lambert is still the hemisphere of radius 1/pi.
        r = run("lobe", "--model", "lambert-normalized", "--incidence", "89.9", "-o", self.out("l.vtp"))
        self.assertEqual(r.returncode, 0, r.stderr)
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(self.out("l.vtp"))
        reader.Update()
        points = vtk_to_numpy(reader.GetOutput().GetPoints().GetData())
        radii = (points.astype(float) ** 2).sum(axis=1) ** 0.5
        self.assertGreater(len(radii), 100)
        self.assertAlmostEqual(radii.min(), 1.0 / 3.141592653589793, places=6)
        self.assertAlmostEqual(radii.max(), 1.0 / 3.141592653589793, places=6)

    def test_lobe_resolution_shows_a_sharp_peak(self):
        """Phong at n = 10^4, 30 degrees: radiance k_s cos^n(alpha), so the slice peaks at 1 / cos 30 at the
        mirror direction. The default rings miss the peak; --theta-resolution 1024 finds it."""
        import vtk
        from vtk.util.numpy_support import vtk_to_numpy
        peak = 1.0 / math.cos(math.radians(30.0))

        def slice_peak(*options):
            r = run("lobe", "--model", "phong", "--shininess", "10000", "--incidence", "30", *options,
                    "-o", self.out("lobe.vtp"), "--slice", self.out("slice.vtp"))
            self.assertEqual(r.returncode, 0, r.stderr)
            reader = vtk.vtkXMLPolyDataReader()
            reader.SetFileName(self.out("slice.vtp"))
            reader.Update()
            points = vtk_to_numpy(reader.GetOutput().GetPoints().GetData()).astype(float)
            return ((points ** 2).sum(axis=1) ** 0.5).max(), reader.GetOutput().GetNumberOfPoints()

        coarse, coarse_points = slice_peak()
        fine, fine_points = slice_peak("--theta-resolution", "1024", "--phi-resolution", "16")
        self.assertGreater(fine_points, 16 * coarse_points)
        self.assertLess(coarse, 0.95 * peak)
        self.assertAlmostEqual(fine / peak, 1.0, delta=0.01)
        r = run("lobe", "--model", "phong", "--theta-resolution", "1025", "-o", self.out("x.vtp"))
        self.assertEqual((r.returncode, r.stderr),
                         (2, "shadelab lobe: --theta-resolution: 1025 is out of range [1, 1024]\n"))

    def test_lobe_of_brdf_files_alone_refuses_model_options(self):
        """A .brdf file's f_r reads its own parameters: the built-in models' options would change nothing."""
        ward = os.path.join(DATA, "brdf", "ward-anisotropic.brdf")
        for option, value, target in (("--kd", "0.3", "x.vtp"), ("--model", "phong", "x.vtp"),
                                      ("--shininess", "5", "x.vtp"), ("--roughness-x", "0.5", "x.png"),
                                      ("--ks", "0.5", "x.png")):
            r = run("lobe", "--brdf", ward, option, value, "-o", self.out(target))
            self.assertEqual(r.returncode, 2, (option, r.stderr))
            self.assertEqual(r.stderr.count("\n"), 1, r.stderr)
            self.assertIn(option + ": only for built-in models; a .brdf file's lobe takes the file's parameters",
                          r.stderr)
            self.assertFalse(os.path.exists(self.out(target)), option)

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
