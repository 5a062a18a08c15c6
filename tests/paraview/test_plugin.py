"""The ShadeLab plugin in pvpython: it loads, and every filter and the
source run from paraview.simple and give their arrays, with values checked
where they are known without ShadeLab (emission only, Lambert's zero
specular, a scene file against the same values set as properties).

    pvpython test_plugin.py PLUGIN MESH.vtp DATA_DIR
"""
import os
import sys
import unittest

from paraview import servermanager
import paraview.simple as pvs
from paraview.simple import LoadPlugin, XMLPolyDataReader

PLUGIN, MESH, DATA = sys.argv[1:4]
del sys.argv[1:4]
# Adds a function per proxy to paraview.simple, named after its label.
LoadPlugin(PLUGIN, remote=False)


def fetch(proxy):
    proxy.UpdatePipeline()
    return servermanager.Fetch(proxy)


def point_array(mesh, name):
    array = mesh.GetPointData().GetArray(name)
    assert array is not None, "no point array %s (arrays: %s)" % (
        name, [mesh.GetPointData().GetArrayName(i) for i in range(mesh.GetPointData().GetNumberOfArrays())])
    return array


class PluginTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.reader = XMLPolyDataReader(FileName=[MESH])
        cls.normals = pvs.ShadeLabNormals(Input=cls.reader)

    def test_every_proxy_is_registered(self):
        for name in ("ShadeLabNormals", "ShadeLabTangents", "ShadeLabNormalMap", "ShadeLabBumpMap",
                     "ShadeLabDisplacement", "ShadeLabRadiance", "ShadeLabCosineField", "ShadeLabBRDFLobesOnMesh",
                     "ShadeLabMonteCarloReference", "ShadeLabBRDFLobe"):
            self.assertTrue(hasattr(pvs, name), name)

    def test_normals_every_weighting(self):
        for weighting in ("Uniform", "Area", "Angle", "Max"):
            f = pvs.ShadeLabNormals(Input=self.reader, Weighting=weighting, AutoOrientNormals=1,
                                    ComputeCellNormals=1)
            mesh = fetch(f)
            normals = point_array(mesh, "Normals")
            self.assertEqual(normals.GetNumberOfComponents(), 3)
            self.assertIsNotNone(mesh.GetCellData().GetArray("Normals"))
            lo, hi = normals.GetRange(-1)
            self.assertAlmostEqual(hi, 1.0, places=5)

    def test_tangents_and_detail(self):
        tangents = fetch(pvs.ShadeLabTangents(Input=self.normals))
        self.assertEqual(point_array(tangents, "Tangents").GetNumberOfComponents(), 4)
        normal_map = os.path.join(DATA, "textures", "bevy_parallax_cube_normal.png")
        depth = os.path.join(DATA, "textures", "bevy_parallax_cube_depth.png")
        for proxy in (pvs.ShadeLabNormalMap(Input=self.normals, NormalMap=normal_map, Strength=0.5),
                      pvs.ShadeLabBumpMap(Input=self.normals, HeightMap=depth, InvertHeight=1),
                      pvs.ShadeLabDisplacement(Input=self.normals, HeightMap=depth, Scale=0.01)):
            mesh = fetch(proxy)
            self.assertGreater(mesh.GetNumberOfPolys(), 0)
            point_array(mesh, "Normals")

    def test_radiance_emission_only(self):
        # k_a = k_d = k_s = 0: the radiance is k_e at every point.
        f = pvs.ShadeLabRadiance(Input=self.normals, OverrideMaterial=1, AmbientColor=[0, 0, 0],
                                 DiffuseColor=[0, 0, 0], SpecularColor=[0, 0, 0], EmissionColor=[0.25, 0.5, 1.0])
        radiance = point_array(fetch(f), "Radiance")
        for c, expected in enumerate((0.25, 0.5, 1.0)):
            self.assertEqual(radiance.GetRange(c), (expected, expected))

    def test_model_property(self):
        # Lambert has no specular term.
        specular = point_array(fetch(pvs.ShadeLabRadiance(Input=self.normals, LightingModel="Lambert")), "Specular")
        self.assertEqual(specular.GetRange(-1), (0.0, 0.0))
        specular = point_array(fetch(pvs.ShadeLabRadiance(Input=self.normals, LightingModel="Phong")), "Specular")
        self.assertGreater(specular.GetRange(-1)[1], 0.0)

    def test_scene_file_and_texture(self):
        scene = os.path.join(DATA, "scenes", "default.json")
        plain = point_array(fetch(pvs.ShadeLabRadiance(Input=self.normals)), "Radiance")
        from_file = point_array(fetch(pvs.ShadeLabRadiance(Input=self.normals, SceneFile=scene)), "Radiance")
        self.assertNotEqual(plain.GetRange(0), from_file.GetRange(0))
        texture = os.path.join(DATA, "meshes", "spot_texture.png")
        textured = point_array(fetch(pvs.ShadeLabRadiance(Input=self.normals, SceneFile=scene,
                                                          DiffuseTexture=texture)), "Radiance")
        self.assertNotEqual(textured.GetRange(0), from_file.GetRange(0))

    def test_missing_scene_file_gives_empty_output(self):
        f = pvs.ShadeLabRadiance(Input=self.normals, SceneFile="/nonexistent/scene.json")
        self.assertEqual(fetch(f).GetNumberOfPoints(), 0)

    def test_cosine_lobes_reference_and_source(self):
        cosine = fetch(pvs.ShadeLabCosineField(Input=self.normals, LightIndex=0))
        lo, hi = point_array(cosine, "CosTheta").GetRange()
        self.assertGreaterEqual(lo, 0.0)
        self.assertLessEqual(hi, 1.0)
        lobes = fetch(pvs.ShadeLabBRDFLobesOnMesh(Input=self.normals, NumberOfLobes=4))
        self.assertGreater(lobes.GetNumberOfPoints(), 0)
        point_array(lobes, "BRDF")
        env = os.path.join(DATA, "envmaps", "studio_small_03_1k.hdr")
        reference = fetch(pvs.ShadeLabMonteCarloReference(Input=self.normals, SamplesPerPoint=2,
                                                        EnvironmentMap=env))
        point_array(reference, "RadianceError")
        lobe = fetch(pvs.ShadeLabBRDFLobe(LightingModel="Blinn-Phong (normalized)", Shininess=40))
        self.assertGreater(point_array(lobe, "BRDF").GetRange()[1], 0.0)


if __name__ == "__main__":
    unittest.main()
