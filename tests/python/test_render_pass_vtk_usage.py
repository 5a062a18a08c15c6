"""slLightingPass in a VTK user's own pipeline: each check predicts the pixel
from the lighting equation (a flat quad facing a directional light: k_d N.L I
255) or from what VTK itself draws, never from the pass's earlier output."""
import math
import re
import unittest

import shadelab
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkLookupTable, vtkUnsignedCharArray
from vtkmodules.vtkFiltersSources import vtkLineSource, vtkPlaneSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper, vtkProperty, vtkRenderer,
                                         vtkRenderWindow, vtkWindowToImageFilter)
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


# A backface property unlike the front one (quad_actor: k_d = 0.8 of COLOUR,
# no ambient, no specular) in every coefficient VTK reads from it.
BACK_AMBIENT, BACK_AMBIENT_COLOUR = 0.2, (0.5, 0.0, 0.0)
BACK_DIFFUSE, BACK_DIFFUSE_COLOUR = 0.6, (0.2, 0.6, 1.0)
BACK_SPECULAR, BACK_SPECULAR_COLOUR, BACK_POWER = 0.4, (1.0, 1.0, 0.5), 8.0
TILT = 0.5  # radians between the light and the normal of the side in view


def backface_property():
    back = vtkProperty()
    back.SetAmbient(BACK_AMBIENT)
    back.SetAmbientColor(*BACK_AMBIENT_COLOUR)
    back.SetDiffuse(BACK_DIFFUSE)
    back.SetDiffuseColor(*BACK_DIFFUSE_COLOUR)
    back.SetSpecular(BACK_SPECULAR)
    back.SetSpecularColor(*BACK_SPECULAR_COLOUR)
    back.SetSpecularPower(BACK_POWER)
    return back


def phong_pixel(ambient, diffuse, specular, power):
    """VTK's (and ShadeLab's Phong model's) equation at a point seen along its
    normal, lit by the stage's directional light TILT off the normal: the
    ambient colour (VTK's implicit white ambient light) plus
    I (k_d C_d cos(TILT) + k_s C_s cos(TILT)^n), R.V being cos(TILT) too.
    Each argument but power is a (coefficient, colour) pair."""
    cos = math.cos(TILT)
    return [round(255.0 * (ambient[0] * a + INTENSITY * (diffuse[0] * d * cos + specular[0] * s * cos ** power)))
            for a, d, s in zip(ambient[1], diffuse[1], specular[1])]


BACK_PIXEL = phong_pixel((BACK_AMBIENT, BACK_AMBIENT_COLOUR), (BACK_DIFFUSE, BACK_DIFFUSE_COLOUR),
                         (BACK_SPECULAR, BACK_SPECULAR_COLOUR), BACK_POWER)
# quad_actor's own material on the side in view.
FRONT_PIXEL = phong_pixel((0.0, COLOUR), (KD, COLOUR), (0.0, COLOUR), 1.0)


def look_at_side(stage, back):
    """Looks at the quad's back (from -z) or front (from +z) along its normal,
    in parallel projection (the same view direction at every point, so every
    frequency gives one colour), with the light TILT off that side's normal."""
    side = -1.0 if back else 1.0
    camera = stage.renderer.GetActiveCamera()
    camera.SetPosition(0, 0, 5 * side)
    camera.SetFocalPoint(0, 0, 0)
    camera.SetViewUp(0, 1, 0)
    camera.ParallelProjectionOn()
    camera.SetParallelScale(1.5)
    stage.light.SetPosition(0, math.sin(TILT), math.cos(TILT) * side)
    stage.light.SetFocalPoint(0, 0, 0)
    stage.renderer.ResetCameraClippingRange()


def tracked(lighting, what):
    """The count PrintSelf reports as `what` (TrackedMappers, TrackedShaderPrograms)."""
    return int(re.search(what + r": (\d+)", str(lighting)).group(1))


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

    def test_backface_property_shades_faces_seen_from_behind_as_in_vtk(self):
        # VTK: faces seen from behind take the backface property's colours,
        # coefficients and specular power, lit with the flipped normal.
        actor = quad_actor()
        actor.SetBackfaceProperty(backface_property())
        stage = Stage(actor)
        look_at_side(stage, back=True)
        self.assertPixel(stage.render(False), BACK_PIXEL)  # VTK's own pixel agrees with the equation
        for frequency in ("flat", "gouraud", "phong"):
            with self.subTest(frequency=frequency):
                lighting = lighting_pass()
                lighting.SetModelName("phong")
                lighting.SetFrequencyName(frequency)
                stage.renderer.SetPass(lighting)
                stage.window.Render()
                self.assertPixel(pixel(stage.window), BACK_PIXEL)
                # The front keeps the front property.
                look_at_side(stage, back=False)
                stage.window.Render()
                self.assertPixel(pixel(stage.window), FRONT_PIXEL)
                look_at_side(stage, back=True)

    def test_without_a_backface_property_the_back_takes_the_front_material(self):
        stage = Stage(quad_actor())
        look_at_side(stage, back=True)
        self.assertPixel(stage.render(True), FRONT_PIXEL)
        self.assertPixel(stage.render(False), FRONT_PIXEL)

    def test_scalar_colours_leave_the_backface_property_unused_as_in_vtk(self):
        # VTK reads the backface property only where the property's colours
        # colour the surface: shown scalars colour both sides with the front
        # property's coefficients.
        actor = quad_actor()
        data = actor.GetMapper().GetInput()
        colours = vtkUnsignedCharArray()
        colours.SetNumberOfComponents(3)
        for _ in range(data.GetNumberOfPoints()):
            colours.InsertNextTuple3(0, 200, 100)
        data.GetPointData().SetScalars(colours)
        actor.SetBackfaceProperty(backface_property())
        stage = Stage(actor)
        look_at_side(stage, back=True)
        scalar = (0.0, 200.0 / 255.0, 100.0 / 255.0)
        wanted = expected(scalar, KD * INTENSITY * math.cos(TILT))
        self.assertPixel(stage.render(False), wanted)
        self.assertPixel(stage.render(True), wanted)

    def test_the_scene_material_shades_both_sides(self):
        # UseSceneMaterial: one material for the whole scene, on both sides;
        # a backface property changes nothing.
        actor = quad_actor()
        actor.SetBackfaceProperty(backface_property())
        stage = Stage(actor)
        look_at_side(stage, back=True)
        scene = shadelab.slScene()
        scene.SetLightsFromVTK(stage.renderer.GetLights())
        material = vtkProperty()
        material.SetAmbient(0.0)
        material.SetDiffuse(0.5)
        material.SetDiffuseColor(0.0, 1.0, 1.0)
        material.SetSpecular(0.0)
        scene.SetMaterialFromVTK(material)
        self.assertTrue(scene.SetModelName("lambert"))
        lighting = shadelab.slLightingPass()
        lighting.SetScene(scene)
        stage.renderer.SetPass(lighting)
        stage.window.Render()
        self.assertPixel(pixel(stage.window), expected((0.0, 1.0, 1.0), 0.5 * INTENSITY * math.cos(TILT)))

    def test_records_of_freed_mappers_and_programs_are_dropped(self):
        # The pass keeps a record per mapper with 4-component tangents and
        # per shader program it sets. Making and freeing many of them (new
        # actors in new windows, each window with its own shader programs)
        # must not grow these records without bound: they stay within about
        # twice the live ones (here 2 mappers and 1 program at a time).
        lighting = lighting_pass()
        for _ in range(30):
            actors = [quad_actor() for _ in range(2)]
            for actor in actors:
                data = actor.GetMapper().GetInput()
                tangents = vtkFloatArray()
                tangents.SetName("Tangents")
                tangents.SetNumberOfComponents(4)
                for _ in range(data.GetNumberOfPoints()):
                    tangents.InsertNextTuple4(1.0, 0.0, 0.0, 1.0)
                data.GetPointData().AddArray(tangents)
            stage = Stage(*actors)
            stage.renderer.SetPass(lighting)
            stage.window.Render()
            self.assertPixel(pixel(stage.window), expected(COLOUR, KD * INTENSITY))
            stage.window.Finalize()
            del stage, actors
        self.assertLessEqual(tracked(lighting, "TrackedMappers"), 2 * 2 + 1)
        self.assertLessEqual(tracked(lighting, "TrackedShaderPrograms"), 2 * 1 + 1)

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
