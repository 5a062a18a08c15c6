"""Makes docs/images/normals-*.png with ShadeLab's own commands and filters.

Run from the repository root, with an X display (scripts/with-display.sh):
  bash scripts/with-display.sh /usr/bin/python3 docs/make_normals_images.py build-normals
The argument is the build folder (its bin/shadelab and python/shadelab are used).
"""
import os
import subprocess
import sys
import tempfile

BUILD = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "build")
sys.path.insert(0, os.path.join(BUILD, "lib", "python3", "dist-packages"))
import shadelab  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkGlyph3D  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkArrowSource, vtkPlaneSource, vtkSphereSource  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter  # noqa: E402
from vtkmodules.vtkRenderingCore import (  # noqa: E402
    vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401
from vtkmodules.vtkFiltersCore import vtkCellCenters  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
IMAGES = os.path.join(ROOT, "docs", "images")
DATA = os.path.join(ROOT, "data")
SHADELAB = os.path.join(BUILD, "bin", "shadelab")


def shadelab_cmd(*args):
    print("shadelab", " ".join(args))
    subprocess.run([SHADELAB, *args], check=True)


def glyphs(points_with_normals, scale, colour):
    arrow = vtkArrowSource()
    g = vtkGlyph3D()
    g.SetInputData(points_with_normals)
    g.SetSourceConnection(arrow.GetOutputPort())
    g.SetVectorModeToUseNormal()
    g.SetScaleFactor(scale)
    g.OrientOn()
    m = vtkPolyDataMapper()
    m.SetInputConnection(g.GetOutputPort())
    a = vtkActor()
    a.SetMapper(m)
    a.GetProperty().SetColor(*colour)
    return a


def surface(mesh, flat):
    m = vtkPolyDataMapper()
    m.SetInputData(mesh)
    a = vtkActor()
    a.SetMapper(m)
    a.GetProperty().SetColor(0.85, 0.85, 0.8)
    if flat:
        a.GetProperty().SetInterpolationToFlat()
    return a


def save(window, name):
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    writer = shadelab.slImageWriter()
    writer.SetInputData(grab.GetOutput())
    writer.SetFileName(os.path.join(IMAGES, name))
    if not writer.Write():
        raise SystemExit(1)  # VTK has printed the writer's one-line reason
    print("wrote", os.path.join("docs", "images", name))


def face_and_vertex_glyphs():
    """A coarse sphere: face normals (cell centres, left) and vertex normals (right)."""
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(10)
    sphere.SetPhiResolution(7)
    sphere.Update()
    f = shadelab.slPolyDataNormals()
    f.SetInputData(sphere.GetOutput())
    f.ComputeCellNormalsOn()
    f.SplittingOff()
    f.Update()
    mesh = f.GetOutput()
    centres = vtkCellCenters()
    centres.SetInputData(mesh)
    centres.Update()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(960, 480)
    for i, (actor, flat) in enumerate(((glyphs(centres.GetOutput(), 0.25, (0.9, 0.3, 0.2)), True),
                                       (glyphs(mesh, 0.25, (0.2, 0.4, 0.9)), False))):
        r = vtkRenderer()
        r.SetViewport(0.5 * i, 0, 0.5 * i + 0.5, 1)
        r.SetBackground(1, 1, 1)
        r.AddActor(surface(mesh, flat))
        r.AddActor(actor)
        r.GetActiveCamera().Elevation(25)
        r.ResetCamera()
        window.AddRenderer(r)
    save(window, "normals-face-vs-vertex.png")


def plane_with_uvs(path, n):
    p = vtkPlaneSource()
    p.SetResolution(n, n)
    p.Update()
    w = vtkXMLPolyDataWriter()
    w.SetInputData(p.GetOutput())
    w.SetFileName(path)
    w.Write()


def main():
    os.makedirs(IMAGES, exist_ok=True)
    face_and_vertex_glyphs()
    with tempfile.TemporaryDirectory() as tmp:
        t = lambda name: os.path.join(tmp, name)  # noqa: E731
        fandisk = os.path.join(DATA, "meshes", "fandisk.obj")
        shadelab_cmd("normals", fandisk, "-o", t("fandisk-split.vtp"))
        shadelab_cmd("normals", fandisk, "--no-split", "-o", t("fandisk-smooth.vtp"))
        with open(t("fandisk.json"), "w") as f:  # a view that shows the sharp edges
            f.write('{ "camera": { "azimuth": 140, "elevation": 35 }, "lights": ['
                    '{ "type": "directional", "space": "camera", "direction": [0.4, -0.5, -1] },'
                    '{ "type": "ambient", "ambient": [0.15, 0.15, 0.15] } ] }')
        for name in ("split", "smooth"):
            shadelab_cmd("render", t("fandisk-" + name + ".vtp"), "--scene", t("fandisk.json"), "--size", "480x400",
                         "-q", "-o", os.path.join(IMAGES, "normals-fandisk-" + name + ".png"))
        normal_map = os.path.join(DATA, "textures", "bevy_parallax_cube_normal.png")
        plane_with_uvs(t("plane.vtp"), 200)
        shadelab_cmd("normals", t("plane.vtp"), "-o", t("plane-n.vtp"))
        shadelab_cmd("detail", t("plane-n.vtp"), "--normal-map", normal_map, "-o", t("plane-mapped.vtp"))
        spot = os.path.join(DATA, "meshes", "spot.obj")
        shadelab_cmd("normals", spot, "-o", t("spot-n.vtp"))
        shadelab_cmd("detail", t("spot-n.vtp"), "--normal-map", normal_map, "--strength", "2", "-o",
                     t("spot-mapped.vtp"))
        for name in ("plane-n", "plane-mapped", "spot-n", "spot-mapped"):
            shadelab_cmd("render", t(name + ".vtp"), "--size", "400x400", "-q", "-o",
                         os.path.join(IMAGES, "normals-" + name + ".png"))


if __name__ == "__main__":
    main()
