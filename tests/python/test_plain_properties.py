"""The lighting filters' plain-value properties (what ParaView's wrapping can
reach): scene file name, lighting model, material values and the diffuse
texture file name, each against a value known without them."""
import os
import sys
import unittest

import shadelab
import vtk

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from spot_mesh import spot_with_normals  # noqa: E402
from vtk_errors import update_error  # noqa: E402

DATA = os.environ["SHADELAB_DATA_DIR"]
SCENE = os.path.join(DATA, "scenes", "default.json")
TEXTURE = os.path.join(DATA, "meshes", "spot_texture.png")


def radiance(configure, array="Radiance"):
    f = shadelab.slRadianceFilter()
    f.SetInputData(spot_with_normals())
    configure(f)
    error = update_error(f)
    out = f.GetOutput().GetPointData().GetArray(array)
    return error, out


def values(array):
    return [array.GetTuple3(i) for i in range(array.GetNumberOfTuples())]


class PlainPropertiesTest(unittest.TestCase):
    def test_scene_file_name_equals_scene_object(self):
        scene = shadelab.slScene()
        self.assertTrue(scene.ReadFile(SCENE))
        error, by_object = radiance(lambda f: f.SetScene(scene))
        self.assertEqual(error, "")
        error, by_name = radiance(lambda f: f.SetSceneFileName(SCENE))
        self.assertEqual(error, "")
        self.assertEqual(values(by_name), values(by_object))
        _, default = radiance(lambda f: None)
        self.assertNotEqual(values(by_name), values(default))

    def test_missing_scene_file_names_it(self):
        error, out = radiance(lambda f: f.SetSceneFileName("/nonexistent/scene.json"))
        self.assertIn("/nonexistent/scene.json", error)
        self.assertIsNone(out)

    def test_emission_only_material(self):
        def configure(f):
            f.OverrideMaterialOn()
            f.SetAmbientColor(0, 0, 0)
            f.SetDiffuseColor(0, 0, 0)
            f.SetSpecularColor(0, 0, 0)
            f.SetEmissionColor(0.25, 0.5, 1.0)
        error, out = radiance(configure)
        self.assertEqual(error, "")
        self.assertEqual(set(values(out)), {(0.25, 0.5, 1.0)})

    def test_material_colour_out_of_range_is_an_error(self):
        # The numbers are clamped by their setters (test_material_setters.py).
        def configure(f):
            f.OverrideMaterialOn()
            f.SetDiffuseColor(-1, 0, 0)
        error, out = radiance(configure)
        self.assertIn("material.diffuse", error)

    def test_material_values_ignored_unless_overriding(self):
        _, default = radiance(lambda f: None)
        _, ignored = radiance(lambda f: f.SetEmissionColor(1, 1, 1))
        self.assertEqual(values(ignored), values(default))

    def test_model(self):
        error, specular = radiance(lambda f: f.SetModel(0), "Specular")  # Lambert
        self.assertEqual(error, "")
        self.assertEqual(specular.GetRange(-1), (0.0, 0.0))
        _, specular = radiance(lambda f: f.SetModel(1), "Specular")  # Phong
        self.assertGreater(specular.GetRange(-1)[1], 0.0)

    def test_diffuse_texture_file_name_equals_image(self):
        image = shadelab.slImageReader()
        image.SetFileName(TEXTURE)
        image.Update()
        _, by_image = radiance(lambda f: f.SetDiffuseTexture(image.GetOutput()))
        error, by_name = radiance(lambda f: f.SetDiffuseTextureFileName(TEXTURE))
        self.assertEqual(error, "")
        self.assertEqual(values(by_name), values(by_image))
        _, plain = radiance(lambda f: None)
        self.assertNotEqual(values(by_name), values(plain))

    def test_missing_texture_file_names_it(self):
        error, out = radiance(lambda f: f.SetDiffuseTextureFileName("/nonexistent/t.png"))
        self.assertIn("/nonexistent/t.png", error)
        self.assertIsNone(out)


if __name__ == "__main__":
    unittest.main()
