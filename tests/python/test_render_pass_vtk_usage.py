"""slLightingPass in a VTK user's own pipeline: each check predicts the pixel
from the lighting equation (a flat quad facing a directional light: k_d N.L I
255) or from what VTK itself draws, never from the pass's earlier output."""
import math
import re
import unittest

import shadelab
from vtkmodules.vtkCommonCore import VTK_UNSIGNED_CHAR, vtkFloatArray, vtkLookupTable, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkLineSource, vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (VTK_FLAT, VTK_GOURAUD, VTK_PHONG, vtkActor, vtkLight, vtkPolyDataMapper,
                                         vtkProperty, vtkRenderer, vtkRenderWindow, vtkTexture,
                                         vtkWindowToImageFilter)
from vtkmodules.vtkRenderingOpenGL2 import (vtkCameraPass, vtkLightsPass, vtkOpaquePass, vtkRenderPassCollection,
                                            vtkRenderStepsPass, vtkSequencePass, vtkShadowMapPass)
import vtkmodules.vtkInteractionStyle  # noqa: F401

SIZE = 64
COLOUR = (1.0, 0.5, 0.25)
KD = 0.8
INTENSITY = 0.5


def grab(window):
    grabber = vtkWindowToImageFilter()
    grabber.SetInput(window)
    grabber.ReadFrontBufferOff()
    grabber.Update()
    return grabber.GetOutput()


def pixel(window, x=SIZE // 2, y=SIZE // 2):
    image = grab(window)
    width = image.GetDimensions()[0]
    return image.GetPointData().GetScalars().GetTuple3(y * width + x)


def picture(window):
    """Every pixel of the window, as bytes (to compare two pictures exactly).
    Like pixel(), it draws the window once more to read it."""
    return bytes(memoryview(grab(window).GetPointData().GetScalars()))


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


def with_point_colours(actor):
    """Gives @p actor's mesh the point scalars (0, 200, 100) at every point."""
    data = actor.GetMapper().GetInput()
    colours = vtkUnsignedCharArray()
    colours.SetNumberOfComponents(3)
    for _ in range(data.GetNumberOfPoints()):
        colours.InsertNextTuple3(0, 200, 100)
    data.GetPointData().SetScalars(colours)

def flat_under_pass(actor, top=None):
    """@p actor with flat interpolation in a Stage of its own, drawn once
    through a new lighting pass (@p top(lighting), a pass around it, as the
    renderer's pass when given): (stage, lighting)."""
    actor.GetProperty().SetInterpolationToFlat()
    stage = Stage(actor)
    lighting = lighting_pass()
    stage.renderer.SetPass(top(lighting) if top else lighting)
    stage.window.Render()
    return stage, lighting


def sequence_of(*steps):
    passes = vtkRenderPassCollection()
    for step in steps:
        passes.AddItem(step)
    sequence = vtkSequencePass()
    sequence.SetPasses(passes)
    return sequence


def flat_sphere_pictures():
    """VTK's own pictures of sphere_actor() in a Stage: smooth (Phong
    interpolation) and with facets (flat), which differ."""
    stage = Stage(sphere_actor())
    stage.window.Render()
    smooth = picture(stage.window)
    stage.renderer.GetActors().GetLastActor().GetProperty().SetInterpolationToFlat()
    stage.window.Render()
    return smooth, picture(stage.window)


def camera_pass_of(*steps):
    """VTK's documented chain: a vtkCameraPass around a vtkSequencePass of @p steps."""
    camera_pass = vtkCameraPass()
    camera_pass.SetDelegatePass(sequence_of(*steps))
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


# The actor's texture: one colour unlike the quad's, so that where it is
# shown the pixel is the quad's colour times it.
TEXTURE_RGB = (64, 255, 128)
TEXTURED_COLOUR = tuple(c * t / 255.0 for c, t in zip(COLOUR, TEXTURE_RGB))


def with_texture(actor):
    """@p actor with a texture of TEXTURE_RGB (vtkPlaneSource gives texture coordinates)."""
    image = vtkImageData()
    image.SetDimensions(2, 2, 1)
    image.AllocateScalars(VTK_UNSIGNED_CHAR, 3)
    texels = image.GetPointData().GetScalars()
    for i in range(texels.GetNumberOfTuples()):
        texels.SetTuple3(i, *TEXTURE_RGB)
    texture = vtkTexture()
    texture.SetInputData(image)
    actor.SetTexture(texture)
    return actor


def texture_line_of(window):
    """The line of the last shader program drawn in @p window (the one
    actor's) that samples the actor's texture."""
    program = window.GetShaderCache().GetLastShaderBound()
    source = program.GetFragmentShader().GetSource()
    return next(line for line in source.splitlines() if "texture(actortexture" in line)


def sphere_actor():
    """A coarse sphere with point normals in quad_actor's material: VTK draws
    it with facets under flat interpolation and smooth otherwise."""
    sphere = vtkSphereSource()
    sphere.SetRadius(1.0)
    sphere.SetThetaResolution(8)
    sphere.SetPhiResolution(6)
    sphere.Update()
    actor = quad_actor()
    actor.GetMapper().SetInputData(sphere.GetOutput())
    return actor


def tracked(lighting, what):
    """The count PrintSelf reports as `what` (TrackedMappers, TrackedShaderPrograms, ...)."""
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
        with_point_colours(actor)
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
        with_point_colours(actor)
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
        # The pass keeps a record per mapper with 4-component tangents, per
        # shader program it sets and per renderer it draws. Making and
        # freeing many of them (new actors in new windows, each window with
        # its own shader programs) must not grow these records without
        # bound: they stay within about twice the live ones (here 2 mappers,
        # 1 program and 1 renderer at a time).
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
        self.assertLessEqual(tracked(lighting, "TrackedRenderers"), 2 * 1 + 1)

    def test_show_textures_on_backface_off_leaves_faces_seen_from_behind_untextured_as_in_vtk(self):
        # VTK 9.1 multiplies the actor's texture into faces seen from behind
        # only while the property's ShowTexturesOnBackface is on (the
        # default); faces seen from the front always show it. The quad lit
        # TILT off the normal of the side in view: k_d C N.L I, times the
        # texture where it is shown.
        actor = with_texture(quad_actor())
        stage = Stage(actor)
        lit = KD * INTENSITY * math.cos(TILT)
        for shown in (True, False):
            actor.GetProperty().SetShowTexturesOnBackface(shown)
            for back in (True, False):
                wanted = expected(TEXTURED_COLOUR if shown or not back else COLOUR, lit)
                look_at_side(stage, back)
                with self.subTest(shown=shown, back=back, drawn_by="vtk"):
                    self.assertPixel(stage.render(False), wanted)
                for frequency in ("flat", "gouraud", "phong"):
                    with self.subTest(shown=shown, back=back, frequency=frequency):
                        lighting = lighting_pass()
                        lighting.SetFrequencyName(frequency)
                        stage.renderer.SetPass(lighting)
                        stage.window.Render()
                        self.assertPixel(pixel(stage.window), wanted)
                        # Only a property with the flag off gets the side
                        # test in its shader; the default costs nothing.
                        texture_line = texture_line_of(stage.window)
                        self.assertEqual("gl_FrontFacing" in texture_line, not shown, texture_line)

    def test_show_textures_on_backface_off_in_vtks_unlit_colour(self):
        # No light and none made automatically: VTK draws the ambient +
        # diffuse colour unlit, times the texture where it is shown.
        actor = with_texture(quad_actor())
        stage = Stage(actor)
        stage.light.SwitchOff()
        stage.renderer.AutomaticLightCreationOff()
        look_at_side(stage, back=True)
        for shown in (True, False):
            with self.subTest(shown=shown):
                actor.GetProperty().SetShowTexturesOnBackface(shown)
                wanted = expected(TEXTURED_COLOUR if shown else COLOUR, KD)
                self.assertPixel(stage.render(False), wanted)
                self.assertPixel(stage.render(True), wanted)

    def test_the_interpolation_is_given_back_when_the_pass_is_taken_out(self):
        # The pass sets a flat property to Phong to light it at Phong
        # frequency; taking the pass out of the renderer gives flat back at
        # once, and VTK's next frame is the one it draws without ever a pass.
        smooth, facets = flat_sphere_pictures()
        self.assertNotEqual(smooth, facets)  # the checks below can tell them apart
        actor = sphere_actor()
        stage, lighting = flat_under_pass(actor)  # Phong frequency
        self.assertEqual(actor.GetProperty().GetInterpolation(), VTK_PHONG)  # while the pass lights it
        for _ in range(2):  # and again after the pass is put back
            stage.renderer.SetPass(None)
            self.assertEqual(actor.GetProperty().GetInterpolation(), VTK_FLAT)
            stage.window.Render()
            self.assertEqual(picture(stage.window), facets)
            stage.renderer.SetPass(lighting)
            stage.window.Render()
            self.assertEqual(actor.GetProperty().GetInterpolation(), VTK_PHONG)
        stage.renderer.SetPass(None)
        del lighting  # freed in the next frame (VTK's mapper holds it until then)
        stage.window.Render()
        self.assertEqual(actor.GetProperty().GetInterpolation(), VTK_FLAT)
        self.assertEqual(picture(stage.window), facets)

    def test_the_interpolation_is_given_back_when_a_pass_taken_out_of_a_pass_around_it_is_freed(self):
        # Out of a pass around it that stays the renderer's, nothing tells
        # the pass; VTK's mapper holds it until it draws without it, and
        # frees it in that frame. Given back once that frame is drawn, the
        # next one is VTK's own (given back in the middle of the frame, VTK
        # would keep the mapper's shaders of the old interpolation, frame
        # after frame).
        _, facets = flat_sphere_pictures()
        actor = sphere_actor()
        stage, lighting = flat_under_pass(actor, sequence_of)
        around = stage.renderer.GetPass()
        around.GetPasses().RemoveAllItems()
        around.GetPasses().AddItem(vtkRenderStepsPass())
        del lighting
        self.assertEqual(actor.GetProperty().GetInterpolation(), VTK_PHONG)  # still held by VTK's mapper
        stage.window.Render()
        self.assertEqual(actor.GetProperty().GetInterpolation(), VTK_FLAT)
        for _ in range(2):
            stage.window.Render()
            self.assertEqual(picture(stage.window), facets)

    def test_passes_changed_around_the_pass_every_frame_rebuild_no_shaders(self):
        # A renderer whose pass changes every frame between two around the
        # lighting pass: the first change is taken for the pass's removal
        # (interpolation given back, set again in the next frame), the
        # others are not, so VTK's shaders are not rebuilt frame after frame.
        actor = sphere_actor()
        actor.GetProperty().SetInterpolationToFlat()
        stage = Stage(actor)
        lighting = lighting_pass()
        arounds = (sequence_of(lighting), sequence_of(lighting))
        for frame in range(8):
            stage.renderer.SetPass(arounds[frame % 2])
            stage.window.Render()
            self.assertEqual(actor.GetProperty().GetInterpolation(), VTK_PHONG)
            if frame == 2:
                builds = lighting.GetNumberOfShaderBuilds()
                changed = actor.GetProperty().GetMTime()
        self.assertEqual(lighting.GetNumberOfShaderBuilds(), builds)
        self.assertEqual(actor.GetProperty().GetMTime(), changed)

    def test_an_interpolation_the_user_changed_is_kept(self):
        # A value the user gives after the pass set its own is the user's:
        # the pass leaves it when it goes, whether a frame was drawn since
        # or not.
        for render_after_change in (False, True):
            with self.subTest(render_after_change=render_after_change):
                actor = quad_actor()
                stage, lighting = flat_under_pass(actor)
                actor.GetProperty().SetInterpolationToGouraud()
                if render_after_change:
                    stage.window.Render()
                    self.assertEqual(actor.GetProperty().GetInterpolation(), VTK_GOURAUD)
                stage.renderer.SetPass(None)
                del lighting
                self.assertEqual(actor.GetProperty().GetInterpolation(), VTK_GOURAUD)

    def test_a_pass_outliving_the_properties_it_changed(self):
        # The pass keeps no property alive, and deleting it after them is safe.
        actor = quad_actor()
        stage, lighting = flat_under_pass(actor)
        stage.renderer.RemoveActor(actor)
        stage.window.Render()
        gone = vtkProperty()
        actor.SetProperty(gone)  # the changed property's last reference goes
        del actor, gone
        stage.renderer.SetPass(None)
        del lighting

    def test_released_graphics_resources_give_the_interpolation_back_and_the_next_frame_takes_it_again(self):
        # VTK releases a renderer's graphics resources, its pass's with them,
        # when its window is finalised (closed, remapped, made full screen)
        # or the renderer is taken out of the window: the pass gives the
        # interpolation back then. The next frame sets it again before
        # anything is drawn: the same picture, and no shader rebuilt and no
        # property modified in the frames after it.
        for release in ("renderer", "window finalised", "renderer removed"):
            with self.subTest(release=release):
                actor = sphere_actor()
                stage, lighting = flat_under_pass(actor)
                before = picture(stage.window)
                if release == "renderer":
                    stage.renderer.ReleaseGraphicsResources(stage.window)
                elif release == "window finalised":
                    stage.window.Finalize()
                else:
                    stage.window.RemoveRenderer(stage.renderer)
                self.assertEqual(actor.GetProperty().GetInterpolation(), VTK_FLAT)
                if release == "renderer removed":
                    stage.window.AddRenderer(stage.renderer)
                stage.window.Render()
                self.assertEqual(actor.GetProperty().GetInterpolation(), VTK_PHONG)
                self.assertEqual(picture(stage.window), before)
                builds = lighting.GetNumberOfShaderBuilds()
                changed = actor.GetProperty().GetMTime()
                for _ in range(3):
                    stage.window.Render()
                self.assertEqual(lighting.GetNumberOfShaderBuilds(), builds)
                self.assertEqual(actor.GetProperty().GetMTime(), changed)
                self.assertEqual(picture(stage.window), before)

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
