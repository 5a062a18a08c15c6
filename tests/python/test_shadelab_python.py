"""import shadelab from Debian's python3 and run its filters."""
import os
import subprocess
import sys
import tempfile
import unittest

import shadelab
from vtkmodules.vtkRenderingCore import vtkLight, vtkRenderer

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from vtk_errors import call_error, update_error  # noqa: E402

DATA = os.environ["SHADELAB_DATA_DIR"]


class ImportTest(unittest.TestCase):
    def test_every_class_is_exported(self):
        for name in ("slMeshReader", "slImageReader", "slImageWriter", "slScene", "slSceneRenderer"):
            self.assertTrue(hasattr(shadelab, name), name)

    def test_import_prints_nothing(self):
        # Loading every library, as a user's script does, says nothing: the
        # dynamic linker complains here about a symbol bound across libraries.
        done = subprocess.run([sys.executable, "-c", "import shadelab; shadelab.slPolyDataNormals()"],
                              capture_output=True, text=True, check=False)
        self.assertEqual((done.returncode, done.stdout, done.stderr), (0, "", ""))


class MeshReaderTest(unittest.TestCase):
    def test_reads_fandisk(self):
        reader = shadelab.slMeshReader()
        reader.SetFileName(os.path.join(DATA, "meshes", "fandisk.obj"))
        self.assertEqual(update_error(reader), "")
        self.assertEqual(reader.GetOutput().GetNumberOfPolys(), 12946)

    def test_error_message_for_missing_file(self):
        reader = shadelab.slMeshReader()
        reader.SetFileName("/nonexistent/m.ply")
        self.assertEqual(update_error(reader), "/nonexistent/m.ply: cannot open file: No such file or directory")
        self.assertEqual(reader.GetOutput().GetNumberOfPoints(), 0)


class ReaderErrorOnStderrTest(unittest.TestCase):
    """A script without an error observer sees each reader's one line on stderr."""

    def stderr_of_update(self, reader_class, path):
        script = f"import shadelab; r = shadelab.{reader_class}(); r.SetFileName({path!r}); r.Update()"
        done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=False)
        return done.stderr

    def test_image_reader(self):
        # The line is written after the capture of the image libraries' own
        # output ends, not into it.
        stderr = self.stderr_of_update("slImageReader", "/nonexistent/x.png")
        self.assertIn("/nonexistent/x.png: cannot read image: ", stderr)

    def test_mesh_reader(self):
        stderr = self.stderr_of_update("slMeshReader", "/nonexistent/m.ply")
        self.assertIn("/nonexistent/m.ply: cannot open file", stderr)


class SceneTest(unittest.TestCase):
    def test_default_scene_to_vtk_lights(self):
        scene = shadelab.slScene()
        self.assertEqual(call_error(scene, lambda: scene.ReadFile(os.path.join(DATA, "scenes", "default.json"))), "")
        self.assertEqual(scene.GetModelName(), "blinn-phong")
        renderer = vtkRenderer()
        scene.ApplyLights(renderer)
        # Four scene lights; the ambient one is folded into the property.
        self.assertEqual(renderer.GetLights().GetNumberOfItems(), scene.GetNumberOfLights() - 1)

    def test_bad_scene_message(self):
        scene = shadelab.slScene()
        self.assertEqual(call_error(scene, lambda: scene.ReadString('{"material": {"shininess": -3}}', "mine.json")),
                         "mine.json: material.shininess: -3 is out of range [0, 100000]")

    def test_vtk_lights_in(self):
        light = vtkLight()
        light.SetPositional(True)
        light.SetPosition(0, 0, 4)
        light.SetConeAngle(180)  # VTK's positional lights are 30-degree spots by default
        renderer = vtkRenderer()
        renderer.AddLight(light)
        scene = shadelab.slScene()
        scene.SetLightsFromVTK(renderer.GetLights())
        self.assertIn('"type": "point"', scene.ToJSON())

    def test_write_and_read_back(self):
        scene = shadelab.slScene()
        self.assertTrue(scene.SetModelName("phong-normalized"))
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "s.json")
            self.assertTrue(scene.WriteFile(path))
            again = shadelab.slScene()
            self.assertEqual(call_error(again, lambda: again.ReadFile(path)), "")
            self.assertEqual(again.GetModelName(), "phong-normalized")


if __name__ == "__main__":
    unittest.main(verbosity=2)
