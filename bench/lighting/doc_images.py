"""Makes docs/images/lighting-*.png from the outputs of the lighting subcommands.

usage (from the repository root, after building into BUILD):
  bash scripts/with-display.sh env PYTHONPATH=BUILD/python /usr/bin/python3 \
      bench/lighting/doc_images.py BUILD/bin/shadelab data docs/images
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np
import vtk
from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy


def read(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def srgb(linear):
    """Linear RGB -> 8-bit sRGB colours (clamped)."""
    c = np.clip(linear, 0.0, 1.0)
    c = np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)
    return numpy_to_vtk((c * 255 + 0.5).astype(np.uint8), deep=True)


def actor_for(mesh, colours=None, scalar=None, scalar_range=None):
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(mesh)
    if colours is not None:
        mesh.GetPointData().SetScalars(colours)
        mapper.SetColorModeToDirectScalars()
        mapper.ScalarVisibilityOn()
    elif scalar is not None:
        mesh.GetPointData().SetActiveScalars(scalar)
        mapper.SetScalarRange(*scalar_range)
        lut = vtk.vtkLookupTable()
        lut.SetHueRange(0.667, 0.0)
        lut.Build()
        mapper.SetLookupTable(lut)
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().LightingOff()
    return actor


def render(actors, path, title, azimuth=140, elevation=12, bar=None):
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    for a in actors:
        renderer.AddActor(a)
    if bar is not None:
        scalar_bar = vtk.vtkScalarBarActor()
        scalar_bar.SetLookupTable(bar)
        scalar_bar.SetNumberOfLabels(5)
        scalar_bar.GetLabelTextProperty().SetColor(0, 0, 0)
        scalar_bar.GetTitleTextProperty().SetColor(0, 0, 0)
        renderer.AddViewProp(scalar_bar)
    text = vtk.vtkTextActor()
    text.SetInput(title)
    text.GetTextProperty().SetColor(0, 0, 0)
    text.GetTextProperty().SetFontSize(18)
    text.SetPosition(10, 10)
    renderer.AddViewProp(text)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(800, 600)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    renderer.GetActiveCamera().Azimuth(azimuth)
    renderer.GetActiveCamera().Elevation(elevation)
    renderer.GetActiveCamera().OrthogonalizeViewUp()
    renderer.ResetCamera()
    renderer.GetActiveCamera().Zoom(1.2)
    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def main():
    shadelab_exe, data_dir, out_dir = sys.argv[1:4]
    data = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "data")
    spot = os.path.join(data, "meshes", "spot.obj")
    texture = os.path.join(data, "meshes", "spot_texture.png")
    venice = os.path.join(data_dir, "envmaps", "venice_sunset_1k.hdr")
    with tempfile.TemporaryDirectory() as tmp:
        def job(*args):
            subprocess.run([shadelab_exe, *args], check=True, capture_output=True)

        # The default scene with a broad Phong lobe, so that the lobes read at this size.
        with open(os.path.join(data, "scenes", "default.json")) as f:
            scene = json.load(f)
        scene.pop("$schema")
        scene["material"].pop("diffuseTexture")
        scene["material"]["shininess"] = 6
        scene["shading"]["model"] = "phong"
        scene_path = os.path.join(tmp, "scene.json")
        with open(scene_path, "w") as f:
            json.dump(scene, f)
        job("light", spot, "--scene", scene_path, "--diffuse-texture", texture, "-o", os.path.join(tmp, "light.vtp"))
        job("lobe", spot, "--scene", scene_path, "--points", "40", "--scale", "0.08", "--cosine",
            "-o", os.path.join(tmp, "lobes.vtp"))
        lit = read(os.path.join(tmp, "light.vtp"))
        lobes = read(os.path.join(tmp, "lobes.vtp"))
        radiance = vtk_to_numpy(lit.GetPointData().GetArray("Radiance"))
        colours = srgb(radiance / np.percentile(radiance.max(axis=1), 99))
        r = vtk_to_numpy(lobes.GetPointData().GetArray("BRDF"))
        lobe_actor = actor_for(lobes, scalar="BRDF", scalar_range=(0.0, float(r.max())))
        render([actor_for(lit, colours=colours), lobe_actor], os.path.join(out_dir, "lighting-lobes-on-spot.png"),
               "shadelab light (Radiance) + shadelab lobe MESH --cosine (Phong, n = 6)")

        job("reference", spot, "--envmap", venice, "--samples", "256", "-o", os.path.join(tmp, "ref.vtp"))
        ref = read(os.path.join(tmp, "ref.vtp"))
        err = vtk_to_numpy(ref.GetPointData().GetArray("RadianceError"))
        luminance = err @ np.array([0.2126, 0.7152, 0.0722])
        arr = numpy_to_vtk(luminance.astype(np.float32), deep=True)
        arr.SetName("ErrorLuminance")
        ref.GetPointData().AddArray(arr)
        limit = float(np.percentile(np.abs(luminance), 98))
        error_actor = actor_for(ref, scalar="ErrorLuminance", scalar_range=(-limit, limit))
        render([error_actor], os.path.join(out_dir, "lighting-reference-error.png"),
               "shadelab reference --envmap venice_sunset_1k.hdr: reference - discrete",
               bar=error_actor.GetMapper().GetLookupTable())


if __name__ == "__main__":
    main()
