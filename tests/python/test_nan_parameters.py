"""A NaN given to a filter's clamped number setter (vtkSetClampMacro keeps
it) fails the next update with one line naming the setter, instead of
hanging, writing NaN or quietly changing the result; the same filter with a
finite value updates."""
import math
import os
import sys
import unittest

import shadelab
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from vtk_errors import call_error, update_error  # noqa: E402

NAN = float("nan")
TEXTURES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "data", "textures")


def sphere():
    s = vtkSphereSource()
    s.SetThetaResolution(12)
    s.SetPhiResolution(8)
    s.Update()
    return s.GetOutput()


def with_input(filter_class):
    def make():
        f = filter_class()
        f.SetInputData(sphere())
        return f
    return make


def detail(filter_class, image):
    """A detail filter on a plane with texture coordinates, reading image."""
    def make():
        plane = vtkPlaneSource()
        plane.SetResolution(8, 8)
        plane.Update()
        f = filter_class()
        f.SetInputData(plane.GetOutput())
        f.SetFileName(os.path.join(TEXTURES, image))
        return f
    return make


def reference():
    f = shadelab.slRadianceReference()
    f.SetInputData(sphere())
    f.SetSamplesPerPoint(4)
    return f


# (filter factory, setter name): every clamped double setter but the
# material's numbers (whose NaN the scene check reports).
CASES = [
    (detail(shadelab.slNormalMapFilter, "bevy_parallax_cube_normal.png"), "Strength"),
    (detail(shadelab.slBumpMapFilter, "bevy_parallax_cube_depth.png"), "Scale"),
    (detail(shadelab.slDisplacementFilter, "bevy_parallax_cube_depth.png"), "Scale"),
    (with_input(shadelab.slPolyDataNormals), "FeatureAngle"),
    (shadelab.slAlbedoTable, "MaximumIncidence"),
    (with_input(shadelab.slLobesOnMesh), "Scale"),
    (reference, "EnvironmentScale"),
    (reference, "LightRadius"),
    (reference, "DirectionalLightAngle"),
    (shadelab.slBRDFLobeSource, "DiffuseWeight"),
    (shadelab.slBRDFLobeSource, "SpecularWeight"),
    (shadelab.slBRDFLobeSource, "IncidenceAngle"),
]


class NaNParameters(unittest.TestCase):
    def test_nan_fails_the_update_with_its_name(self):
        for make, name in CASES:
            with self.subTest(name=name):
                f = make()
                self.assertEqual(update_error(f), "", "finite default")
                getattr(f, "Set" + name)(NAN)
                self.assertTrue(math.isnan(getattr(f, "Get" + name)()), "the setter keeps a NaN")
                self.assertEqual(update_error(f), name + ": nan is not a finite number")
                getattr(f, "Set" + name)(1.0)
                self.assertEqual(update_error(f), "", "a finite value again")


    def test_nan_feature_angle_stops_the_scene_renderer(self):
        # slSceneRenderer computes normals before it draws: Prepare() checks.
        renderer = shadelab.slSceneRenderer()
        renderer.SetScene(shadelab.slScene())
        renderer.SetMesh(sphere())
        renderer.SetFeatureAngle(NAN)
        self.assertEqual(call_error(renderer, renderer.Prepare), "FeatureAngle: nan is not a finite number")


if __name__ == "__main__":
    unittest.main()
