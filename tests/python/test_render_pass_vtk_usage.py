"""slLightingPass in a VTK user's own pipeline: each check predicts the pixel
from the lighting equation (a flat quad facing a directional light: k_d N.L I
255) or from what VTK itself draws, never from the pass's earlier output."""
import unittest

import shadelab
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkLookupTable, vtkUnsignedCharArray
from vtkmodules.vtkFiltersSources import vtkLineSource, vtkPlaneSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)
from vtkmodules.vtkRenderingOpenGL2 import (vtkCameraPass, vtkLightsPass, vtkOpaquePass, vtkRenderPassCollection,
                                            vtkRenderStepsPass, vtkSequencePass, vtkShadowMapPass)
import vtkmodules.vtkInteractionStyle  # noqa: F401

SIZE = 64
COLOUR = (1.0, 0.5, 0.25)
KD = 0.8
INTENSITY = 0.5


def pixel(window, x=SIZE // 2, y=SIZE // 2):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    image = grab.GetOutput()
    width = image.GetDimensions()[0]
    return image.GetPointData().GetScalars().GetTuple3(y * width + x)


def quad_actor():
    """A 2 x 2 quad in z = 0 facing +z (normal (0, 0, 1)), k_d = 0.8, k_a = k_s = 0."""
    plane = vtkPlaneSource()
    plane.SetOrigin(-1, -1, 0)
    plane.SetPoint1(1, -1, 0)
    plane.SetPoint2(-1, 1, 0)
    plane.Update()
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(plane.GetOutput())
    actor = vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    prop.SetColor(*COLOUR)
    prop.SetAmbient(0.0)
    prop.SetDiffuse(KD)
    prop.SetSpecular(0.0)
    return actor


def lighting_pass():
    lighting = shadelab.slLightingPass()
    lighting.SetUseSceneMaterial(False)  # each actor's vtkProperty
    lighting.SetModelName("lambert")
    return lighting


class Stage:
    """A window with one renderer looking at the quad down -z, lit by one
    directional light of intensity 0.5 along -z (N.L = 1)."""

    def __init__(self, *actors):
        self.renderer = vtkRenderer()
        for actor in actors:
            self.renderer.AddActor(actor)
        self.light = vtkLight()
        self.light.SetPositional(False)
        self.light.SetPosition(0, 0, 1)
        self.light.SetFocalPoint(0, 0, 0)
        self.light.SetIntensity(INTENSITY)
        self.renderer.AddLight(self.light)
        self.window = vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        self.window.SetMultiSamples(0)
        self.window.SetSize(SIZE, SIZE)
        self.window.AddRenderer(self.renderer)
        self.renderer.GetActiveCamera().SetPosition(0, 0, 5)  # the quad fills the middle 3/4
        self.renderer.ResetCameraClippingRange()

    def render(self, with_pass):
        self.renderer.SetPass(lighting_pass() if with_pass else None)
        self.window.Render()
        return pixel(self.window)


def camera_pass_of(*steps):
    """VTK's documented chain: a vtkCameraPass around a vtkSequencePass of @p steps."""
    passes = vtkRenderPassCollection()
    for step in steps:
        passes.AddItem(step)
    sequence = vtkSequencePass()
    sequence.SetPasses(passes)
    camera_pass = vtkCameraPass()
    camera_pass.SetDelegatePass(sequence)
    return camera_pass


def expected(colour, factor):
    return [round(255.0 * c * factor) for c in colour]


class VTKUsageTest(unittest.TestCase):
    def assertPixel(self, actual, wanted, delta=1.0):
        for c in range(3):
            self.assertAlmostEqual(actual[c], wanted[c], delta=delta, msg=f"{actual} != {wanted}")

    def test_flat_quad_facing_a_directional_light(self):
        stage = Stage(quad_actor())
        self.assertPixel(stage.render(True), expected(COLOUR, KD * INTENSITY))

    def test_around_a_camera_pass_of_a_sequence_as_vtks_examples_build_it(self):
        lighting = lighting_pass()
        lighting.SetDelegatePass(camera_pass_of(vtkLightsPass(), vtkOpaquePass()))
        stage = Stage(quad_actor())
        stage.renderer.SetPass(lighting)
        stage.window.Render()
        self.assertPixel(pixel(stage.window), expected(COLOUR, KD * INTENSITY))

    def test_all_lights_off_lights_as_vtks_automatic_headlight(self):
        # VTK adds a white headlight of intensity 1 when no light is on
        # (AutomaticLightCreation): k_d N.L 1.
        stage = Stage(quad_actor())
        stage.light.SwitchOff()
        self.assertPixel(stage.render(True), expected(COLOUR, KD))
        self.assertPixel(stage.render(False), expected(COLOUR, KD))  # VTK agrees

    def test_no_light_at_all_is_drawn_unlit_as_vtk_draws_it(self):
        # Without lights and without automatic creation VTK draws the
        # ambient + diffuse colour unlit: (0 + 0.8) * colour.
        stage = Stage(quad_actor())
        stage.light.SwitchOff()
        stage.renderer.AutomaticLightCreationOff()
        self.assertPixel(stage.render(True), expected(COLOUR, KD))
        self.assertPixel(stage.render(False), expected(COLOUR, KD))

    def test_point_scalars_replace_the_property_colour(self):
        # VTK: with scalars shown, the scalar colour takes the place of the
        # property's ambient and diffuse colours (its intensities stay).
        actor = quad_actor()
        data = actor.GetMapper().GetInput()
        colours = vtkUnsignedCharArray()
        colours.SetNumberOfComponents(3)
        for _ in range(data.GetNumberOfPoints()):
            colours.InsertNextTuple3(0, 200, 100)
        data.GetPointData().SetScalars(colours)
        stage = Stage(actor)
        scalar = (0.0, 200.0 / 255.0, 100.0 / 255.0)
        self.assertPixel(stage.render(True), expected(scalar, KD * INTENSITY))
        self.assertPixel(stage.render(False), expected(scalar, KD * INTENSITY))

        # k_a = 1, k_d = 0: the scalar colour under VTK's implicit white
        # ambient light of intensity 1.
        actor.GetProperty().SetAmbient(1.0)
        actor.GetProperty().SetDiffuse(0.0)
        self.assertPixel(stage.render(True), expected(scalar, 1.0))
        self.assertPixel(stage.render(False), expected(scalar, 1.0))

    def test_scalars_through_a_lookup_table_colour_as_in_vtk(self):
        # Point scalars mapped per vertex or through VTK's colour texture map
        # (InterpolateScalarsBeforeMapping, ParaView's default) and cell
        # scalars: the table's one colour in place of the property's.
        green = (0.0, 1.0, 0.0)
        for interpolate, cells in ((False, False), (True, False), (False, True)):
            with self.subTest(interpolate=interpolate, cells=cells):
                actor = quad_actor()
                data = actor.GetMapper().GetInput()
                values = vtkFloatArray()
                for _ in range(data.GetNumberOfCells() if cells else data.GetNumberOfPoints()):
                    values.InsertNextValue(0.5)
                (data.GetCellData() if cells else data.GetPointData()).SetScalars(values)
                table = vtkLookupTable()
                table.SetNumberOfTableValues(1)
                table.SetTableValue(0, *green, 1.0)
                table.SetTableRange(0.0, 1.0)
                mapper = actor.GetMapper()
                mapper.SetLookupTable(table)
                mapper.SetScalarRange(0.0, 1.0)
                mapper.SetInterpolateScalarsBeforeMapping(interpolate)
                mapper.SetScalarMode(2 if cells else 1)  # VTK_SCALAR_MODE_USE_CELL_DATA / _POINT_DATA
                stage = Stage(actor)
                self.assertPixel(stage.render(True), expected(green, KD * INTENSITY))
                self.assertPixel(stage.render(False), expected(green, KD * INTENSITY))

    def test_lines_without_normals_are_drawn_unlit_as_vtk_draws_them(self):
        # VTK lights lines only with point normals; without, it draws the
        # ambient + diffuse colour.
        line = vtkLineSource()
        line.SetPoint1(-1, 0, 0)
        line.SetPoint2(1, 0, 0)
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(line.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(*COLOUR)
        actor.GetProperty().SetAmbient(0.0)
        actor.GetProperty().SetDiffuse(KD)
        actor.GetProperty().SetLineWidth(5)
        stage = Stage(actor)
        self.assertPixel(stage.render(True), expected(COLOUR, KD))
        self.assertPixel(stage.render(False), expected(COLOUR, KD))

    def test_actors_the_pass_leaves_to_vtk_keep_their_interpolation(self):
        # The pass matches the interpolation of the actors it lights to its
        # frequency; a translucent actor or one with lighting off is VTK's,
        # drawn as without the pass.
        lit = quad_actor()
        translucent = quad_actor()
        translucent.GetProperty().SetOpacity(0.5)
        unlit = quad_actor()
        unlit.GetProperty().LightingOff()
        for actor in (lit, translucent, unlit):
            actor.GetProperty().SetInterpolationToFlat()
        stage = Stage(lit, translucent, unlit)
        stage.render(True)  # Phong frequency
        self.assertEqual(lit.GetProperty().GetInterpolation(), 2)  # VTK_PHONG
        self.assertEqual(translucent.GetProperty().GetInterpolation(), 0)  # VTK_FLAT
        self.assertEqual(unlit.GetProperty().GetInterpolation(), 0)

    def test_viewports_each_with_its_own_pass_and_lights(self):
        left = Stage(quad_actor())
        right = vtkRenderer()
        right.AddActor(quad_actor())
        light = vtkLight()
        light.SetPositional(False)
        light.SetPosition(0, 0, 1)
        light.SetFocalPoint(0, 0, 0)
        light.SetIntensity(1.0)
        right.AddLight(light)
        right.GetActiveCamera().SetPosition(0, 0, 5)
        right.ResetCameraClippingRange()
        left.renderer.SetViewport(0.0, 0.0, 0.5, 1.0)
        right.SetViewport(0.5, 0.0, 1.0, 1.0)
        left.window.SetSize(2 * SIZE, SIZE)
        left.window.AddRenderer(right)
        left.renderer.SetPass(lighting_pass())
        right.SetPass(lighting_pass())
        left.window.Render()
        self.assertPixel(pixel(left.window, SIZE // 2, SIZE // 2), expected(COLOUR, KD * INTENSITY))
        self.assertPixel(pixel(left.window, SIZE + SIZE // 2, SIZE // 2), expected(COLOUR, KD))

    def test_shadows_it_cannot_draw_are_reported_once(self):
        # VTK's shadow set-up (vtkShadowMapPass after its baker, in a camera
        # pass) as the pass's delegate: the pass's lighting replaces the
        # terms the shadow maps scale, so it says so, once.
        shadows = vtkShadowMapPass()
        stage = Stage(quad_actor())
        stage.light.SetPositional(True)
        stage.light.SetConeAngle(60)
        lighting = lighting_pass()
        lighting.SetDelegatePass(camera_pass_of(shadows.GetShadowMapBakerPass(), shadows))
        warnings = []
        lighting.AddObserver("WarningEvent", lambda caller, event: warnings.append(event))
        stage.renderer.SetPass(lighting)
        stage.window.Render()
        stage.window.SetSize(SIZE + 8, SIZE)  # new shadow maps, the same shaders
        stage.window.Render()
        self.assertEqual(len(warnings), 1)
        stage.renderer.SetPass(None)
        shadows.GetShadowMapBakerPass().ReleaseGraphicsResources(stage.window)
        shadows.ReleaseGraphicsResources(stage.window)

    def test_setters_modify_only_on_a_change(self):
        lighting = shadelab.slLightingPass()
        delegate = vtkRenderStepsPass()
        lighting.SetDelegatePass(delegate)
        scene = shadelab.slScene()
        lighting.SetScene(scene)
        before = lighting.GetMTime()
        lighting.SetDelegatePass(delegate)
        lighting.SetScene(scene)
        lighting.SetModel(lighting.GetModel())
        lighting.SetFrequency(lighting.GetFrequency())
        lighting.SetComponent(lighting.GetComponent())
        lighting.SetComponentLight(lighting.GetComponentLight())
        lighting.SetFalseColor(lighting.GetFalseColor())
        lighting.SetUseSceneMaterial(lighting.GetUseSceneMaterial())
        self.assertEqual(lighting.GetMTime(), before)
        lighting.SetDelegatePass(vtkRenderStepsPass())
        self.assertGreater(lighting.GetMTime(), before)

    def test_print_self_names_every_setting(self):
        lighting = shadelab.slLightingPass()
        lighting.SetComponentLight(3)
        self.assertTrue(lighting.SetBrdfText(
            "analytic\n::begin parameters\nfloat n 1 1000 42\ncolor tint 0.1 0.2 0.3\n::end parameters\n"
            "::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return tint * n; }\n"
            "::end shader\n", "test.brdf"))
        text = str(lighting)
        for setting in ("Model: blinn-phong", "Frequency: phong", "UseSceneMaterial: 1", "Component: 0",
                        "ComponentLight: 3", "FalseColor: 0", "Brdf: test.brdf", "n: 42", "tint: 0.1 0.2 0.3",
                        "Scene: ", "DelegatePass: "):
            self.assertIn(setting, text)


if __name__ == "__main__":
    unittest.main(verbosity=2)
