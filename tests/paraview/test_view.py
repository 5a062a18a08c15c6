"""The ShadeLab Render View (slLightingRenderView): ParaView's render view
drawing opaque geometry through ShadeLab's lighting pass.

    pvbatch [--symmetric] test_view.py PLUGIN MESH.vtp WORK_DIR

Renders Spot under a scene whose material is emission only: the lighting
pass gives every surface pixel exactly k_e (ParaView's own lighting has no
emission term and would shade the grey surface grey). On several ranks the
composited image blends the silhouette with the background, so there the
surface pixels must be k_e times their coverage. On one process it also
checks that the Flat frequency differs from Phong (the pass takes the
view's frequency).

In ParaView's GUI (test_gui_view.sh) the same checks run as the GUI's
startup script, where the views are created in the GUI's layout and drawn
by its render widgets. There the arguments come from SHADELAB_VIEW_TEST
("PLUGIN MESH.vtp WORK_DIR"), and the outcome (ok, or the failure) is
written to WORK_DIR/gui-result.txt before the GUI is left: a failing
script would otherwise leave the GUI open.
"""
import collections
import json
import os
import sys

import paraview.simple as pvs
from paraview.modules.vtkRemotingCore import vtkProcessModule
from paraview.simple import CreateView, LoadPlugin, Render, SaveScreenshot, Show, XMLPolyDataReader
from vtkmodules.vtkIOImage import vtkPNGReader

GUI = "SHADELAB_VIEW_TEST" in os.environ
plugin, mesh, work = os.environ["SHADELAB_VIEW_TEST"].split() if GUI else sys.argv[1:4]
LoadPlugin(plugin, remote=False)
ranks = vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
rank = vtkProcessModule.GetProcessModule().GetPartitionId()
EMISSION = (0.25, 0.5, 1.0)
BACKGROUND = (0.0, 0.0, 0.0)

scene = os.path.join(work, "emission.json")
if rank == 0:
    with open(scene, "w") as f:
        json.dump({"material": {"ambient": [0, 0, 0], "diffuse": [0, 0, 0], "specular": [0, 0, 0],
                                "emission": list(EMISSION)},
                   "lights": [{"type": "directional", "direction": [0, 0, -1]}]}, f)


def render(source, path, **view_properties):
    view = CreateView("ShadeLabRenderView", **view_properties)
    if GUI:
        # Into the GUI's layout, where its view widget draws it.
        pvs.AssignViewToLayout(view)
        if pvs.GetLayout(view) is None:
            sys.exit("the GUI did not place the ShadeLab Render View in its layout")
    view.ViewSize = [320, 240]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = list(BACKGROUND)
    display = Show(source, view)
    pvs.ColorBy(display, ("POINTS", None))
    view.ResetCamera()
    Render(view)
    SaveScreenshot(path, view, ImageResolution=[320, 240])
    return path


def pixels(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    scalars = reader.GetOutput().GetPointData().GetScalars()
    return [tuple(int(v) for v in scalars.GetTuple(i)[:3]) for i in range(scalars.GetNumberOfTuples())]


def main():
    reader = XMLPolyDataReader(FileName=[mesh])
    normals = pvs.ShadeLabNormals(Input=reader)
    emission = render(normals, os.path.join(work, "emission-%d.png" % ranks), SceneFile=scene)
    if rank == 0:
        surface = [p for p in pixels(emission) if p != tuple(int(255 * b) for b in BACKGROUND)]
        colour, count = collections.Counter(surface).most_common(1)[0]
        expected = [255 * e for e in EMISSION]
        print("emission-only scene: %d surface pixels, %d of them %s (expected %s)" % (
            len(surface), count, colour, expected))
        if len(surface) < 1000 or count < (0.95 if ranks == 1 else 0.8) * len(surface):
            sys.exit("the surface is not one colour: the view is not lit by the scene's emission")
        if any(abs(c - e) > 1 for c, e in zip(colour, expected)):
            sys.exit("surface colour %s is not k_e = %s" % (colour, expected))
        # Every surface pixel is k_e times a coverage t (8-bit rounding: 1.5).
        for p in surface:
            t = p[2] / expected[2]
            if any(abs(c - t * e) > 1.5 for c, e in zip(p, expected)):
                sys.exit("surface pixel %s is not a multiple of k_e = %s" % (p, expected))

    if ranks == 1:
        flat = pixels(render(normals, os.path.join(work, "flat.png"), ShadingFrequency="Flat"))
        phong = pixels(render(normals, os.path.join(work, "phong.png"), ShadingFrequency="Phong"))
        differing = sum(1 for a, b in zip(flat, phong) if a != b)
        print("flat against phong: %d pixels differ" % differing)
        if differing < 100:
            sys.exit("Flat and Phong frequencies give the same image: the view ignores its frequency")


if not GUI:
    main()
else:
    try:
        main()
        outcome = "ok"
    except SystemExit as failure:
        outcome = str(failure.code)
    except Exception as failure:  # reported in the result, as any failure
        outcome = "%s: %s" % (type(failure).__name__, failure)
    with open(os.path.join(work, "gui-result.txt"), "w") as f:
        f.write(outcome + "\n")
    os._exit(0)  # the GUI has no exit from its Python shell
