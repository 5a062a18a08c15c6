"""slLightingPass from Python: a VTK user's own pipeline, lights and camera."""
import os
import unittest

import shadelab
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL render window)
import vtkmodules.vtkInteractionStyle  # noqa: F401


def centre_pixel(window):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    image = grab.GetOutput()
    w, h, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    return scalars.GetTuple3((h // 2) * w + w // 2)


class RenderPassTest(unittest.TestCase):
    def setUp(self):
        sphere = vtkSphereSource()
        sphere.SetThetaResolution(64)
        sphere.SetPhiResolution(64)
        normals = vtkPolyDataNormals()
        normals.SetInputConnection(sphere.GetOutputPort())
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(normals.GetOutputPort())
        self.actor = vtkActor()
        self.actor.SetMapper(mapper)
        self.actor.GetProperty().SetDiffuseColor(1.0, 1.0, 1.0)
        self.actor.GetProperty().SetAmbient(0.0)
        self.actor.GetProperty().SetSpecular(0.0)
        self.renderer = vtkRenderer()
        self.renderer.AddActor(self.actor)
        self.renderer.RemoveAllLights()
        light = vtkLight()  # a VTK user's own light: a directional light along the view
        light.SetPositional(False)
        light.SetPosition(0, 0, 1)
        light.SetFocalPoint(0, 0, 0)
        self.renderer.AddLight(light)
        self.window = vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        self.window.SetSize(64, 64)
        self.window.AddRenderer(self.renderer)
        self.renderer.GetActiveCamera().SetPosition(0, 0, 5)
        self.renderer.ResetCameraClippingRange()

    def test_lambert_from_vtk_lights_and_property(self):
        lighting = shadelab.slLightingPass()
        lighting.SetUseSceneMaterial(False)  # material from the vtkProperty
        self.assertTrue(lighting.SetModelName("lambert"))
        self.renderer.SetPass(lighting)
        self.window.Render()
        # The sphere's centre faces the light: N.L = 1, k_d = 1 -> white.
        self.assertEqual(centre_pixel(self.window), (255.0, 255.0, 255.0))

        self.assertTrue(lighting.SetModelName("lambert-normalized"))  # rho / pi
        self.window.Render()
        self.assertAlmostEqual(centre_pixel(self.window)[0], 255.0 / 3.14159265, delta=1.0)

    def test_component_view(self):
        lighting = shadelab.slLightingPass()
        lighting.SetUseSceneMaterial(False)
        lighting.SetComponent(shadelab.slLightingPass.SPECULAR)
        self.renderer.SetPass(lighting)
        self.window.Render()
        self.assertEqual(centre_pixel(self.window), (0.0, 0.0, 0.0))  # k_s = 0


if __name__ == "__main__":
    unittest.main(verbosity=2)
