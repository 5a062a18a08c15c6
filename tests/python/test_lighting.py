"""The lighting filters from Python: VTK's own lights drive slRadianceFilter,
and the other lighting classes are wrapped and produce their arrays."""
import math
import os
import sys
import unittest

import shadelab
import vtk

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from vtk_errors import update_error  # noqa: E402


def sphere(resolution=12):
    source = vtk.vtkSphereSource()
    source.SetThetaResolution(resolution)
    source.SetPhiResolution(resolution)
    source.Update()
    return source.GetOutput()


class RadianceFromVTKLightsTest(unittest.TestCase):
    def test_renderer_lights_property_and_camera(self):
        renderer = vtk.vtkRenderer()
        light = vtk.vtkLight()
        light.SetLightTypeToSceneLight()
        light.SetPositional(False)
        light.SetPosition(0, 0, 1)
        light.SetFocalPoint(0, 0, 0)
        light.SetAmbientColor(0, 0, 0)
        renderer.AddLight(light)
        prop = vtk.vtkProperty()
        prop.SetDiffuse(1.0)
        prop.SetDiffuseColor(0.5, 0.5, 0.5)
        prop.SetAmbient(0.0)
        prop.SetSpecular(0.0)
        camera = vtk.vtkCamera()
        camera.SetPosition(0, 0, 5)

        f = shadelab.slRadianceFilter()
        f.SetLights(renderer.GetLights())
        f.SetProperty(prop)
        f.SetCamera(camera)
        mesh = sphere()
        f.SetInputData(mesh)
        self.assertEqual(update_error(f), "")
        out = f.GetOutput()
        diffuse = out.GetPointData().GetArray("Diffuse")
        normals = mesh.GetPointData().GetNormals()
        for i in range(mesh.GetNumberOfPoints()):
            n = normals.GetTuple3(i)
            expected = 0.5 * max(0.0, n[2] / math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2))
            self.assertAlmostEqual(diffuse.GetComponent(i, 0), expected, places=5)
        for name in ("Ambient", "Specular", "Emission", "Radiance"):
            self.assertEqual(out.GetPointData().GetArray(name).GetNumberOfComponents(), 3)

    def test_error_message_for_empty_mesh(self):
        f = shadelab.slRadianceFilter()
        f.SetInputData(vtk.vtkPolyData())
        self.assertEqual(update_error(f), "input mesh: it is empty (no points)")
        self.assertEqual(f.GetOutput().GetNumberOfPoints(), 0)


class OtherLightingClassesTest(unittest.TestCase):
    def test_cosine_lobes_albedo_reference(self):
        cosine = shadelab.slCosineField()
        cosine.SetInputData(sphere())
        cosine.Update()
        self.assertIsNotNone(cosine.GetOutput().GetPointData().GetArray("CosThetaRaw_0"))

        lobe = shadelab.slBRDFLobeSource()
        lobe.SetModel(3)
        lobe.SetDiffuseWeight(1.0)
        lobe.Update()
        r = lobe.GetOutput().GetPointData().GetArray("BRDF")
        self.assertAlmostEqual(r.GetRange()[1], 1 / math.pi, places=5)

        table = shadelab.slAlbedoTable()
        table.SetNumberOfAngles(3)
        table.SetMaximumIncidence(89.9)
        table.Update()
        self.assertAlmostEqual(table.GetOutput().GetValueByName(2, "IncidenceDegrees").ToDouble(), 89.9)
        self.assertAlmostEqual(table.GetOutput().GetValueByName(2, "lambert-normalized").ToDouble(), 1.0, places=6)
        # Oren-Nayar at roughness 0 is the normalised Lambert.
        table.SetMaterialParameter("roughness", 0.0)
        table.Update()
        self.assertAlmostEqual(table.GetOutput().GetValueByName(2, "oren-nayar").ToDouble(), 1.0, places=6)

        sky = vtk.vtkImageData()
        sky.SetDimensions(8, 4, 1)
        pixels = vtk.vtkFloatArray()
        pixels.SetNumberOfComponents(3)
        for _ in range(32):
            pixels.InsertNextTuple3(1, 1, 1)
        sky.GetPointData().SetScalars(pixels)
        reference = shadelab.slRadianceReference()
        reference.SetInputData(sphere(6))
        reference.SetEnvironmentMap(sky)
        reference.UseSceneLightsOff()
        reference.SetSamplesPerPoint(8)
        self.assertEqual(update_error(reference), "")
        self.assertIsNotNone(reference.GetOutput().GetPointData().GetArray("RadianceStdError"))


if __name__ == "__main__":
    unittest.main()
