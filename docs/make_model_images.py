"""Makes docs/images/models-*.png and the albedo table of docs/models.md with
ShadeLab's own filters and renderers: every lighting model on the same mesh,
light and camera (data/scenes/models.json), their lobes and albedo curves, and
the pictures of the tutorial "From Blinn-Phong to microfacets".

Run from the repository root, with an X display (scripts/with-display.sh):
  bash scripts/with-display.sh /usr/bin/python3 docs/make_model_images.py [BUILD] [FOLDER]
BUILD is the build folder (its lib/python3/dist-packages/shadelab is used;
default build), FOLDER where the images go (default docs/images).
"""
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build"))
OUT = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "docs", "images"))
sys.path.insert(0, os.path.join(BUILD, "lib", "python3", "dist-packages"))
import numpy  # noqa: E402
import shadelab  # noqa: E402
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImageData  # noqa: E402

SPOT = os.path.join(ROOT, "data", "meshes", "spot.obj")
SCENE = os.path.join(ROOT, "data", "scenes", "models.json")
PANEL = (300, 225)
LECTURE = ("lambert", "phong", "blinn-phong")


def fail(what):
    raise SystemExit("make_model_images.py: " + what)  # VTK has printed the one-line reason


def spot_with_tangents():
    """Spot with MikkTSpace tangents (the anisotropic models need them)."""
    reader = shadelab.slMeshReader()
    reader.SetFileName(SPOT)
    tangents = shadelab.slPolyDataTangents()
    tangents.SetInputConnection(reader.GetOutputPort())
    tangents.Update()
    if tangents.GetOutput().GetNumberOfPoints() == 0:
        fail("no tangents for " + SPOT)
    return tangents.GetOutput()


def cli_grid(name):
    """Every model under data/scenes/models.json as the command line draws
    them: shadelab tangents, then shadelab compare --grid all."""
    program = os.path.join(BUILD, "bin", "shadelab")
    with tempfile.TemporaryDirectory() as folder:
        spot = os.path.join(folder, "spot.vtp")
        for args in (["tangents", SPOT, "-o", spot],
                     ["compare", spot, "--scene", SCENE, "--grid", "all", "--size", "%dx%d" % PANEL,
                      "-o", os.path.join(OUT, name)]):
            if subprocess.run([program] + args).returncode != 0:
                fail("shadelab " + args[0])


def base_scene():
    with open(SCENE) as f:
        return json.load(f)


def for_model(scene, model):
    """The scene for @p model: the lecture models read a light's colour as the
    light reflected at normal incidence, the BRDFs as irradiance, so their
    directional lights get intensity pi (a white lambert-normalized surface
    then looks as under lambert at intensity 1)."""
    scene = json.loads(json.dumps(scene))
    if model not in LECTURE:
        for light in scene["lights"]:
            if light["type"] != "ambient":
                light["intensity"] = math.pi * light.get("intensity", 1.0)
    return scene


def cell(mesh, scene, label, model):
    """One labelled panel: @p mesh under @p scene drawn with @p model (numpy RGB, row 0 at the top)."""
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(scene, f)
    try:
        s = shadelab.slScene()
        if not s.ReadFile(f.name):
            fail("scene for " + label)
    finally:
        os.unlink(f.name)
    r = shadelab.slComparisonRenderer()
    r.SetScene(s)
    r.SetMesh(mesh)
    r.SetPanelWidth(PANEL[0])
    r.SetPanelHeight(PANEL[1])
    r.AddPanel(label, model, "phong")
    if not r.Render():
        fail("rendering " + label)
    return rgb(r.GetImage())


def rgb(image):
    w, h, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3]
    return pixels[::-1].copy()


def tile(rows, background):
    """Rows of panels into one picture; short rows are centred."""
    h = max(p.shape[0] for row in rows for p in row)
    w = max(sum(p.shape[1] for p in row) for row in rows)
    canvas = numpy.empty((h * len(rows), w, 3), numpy.uint8)
    canvas[:] = numpy.round(numpy.array(background) * 255).astype(numpy.uint8)
    for i, row in enumerate(rows):
        x = (w - sum(p.shape[1] for p in row)) // 2
        for p in row:
            canvas[i * h:i * h + p.shape[0], x:x + p.shape[1]] = p
            x += p.shape[1]
    return canvas


def write(pixels, name):
    h, w, _ = pixels.shape
    image = vtkImageData()
    image.SetDimensions(w, h, 1)
    scalars = numpy_to_vtk(numpy.ascontiguousarray(pixels[::-1]).reshape(-1, 3), deep=True)
    image.GetPointData().SetScalars(scalars)
    writer = shadelab.slImageWriter()
    writer.SetInputData(image)
    writer.SetFileName(os.path.join(OUT, name))
    if not writer.Write():
        fail("writing " + name)
    print("wrote", os.path.join(OUT, name))


def lobes(name, models, incidence, numbers=None, kd=0.0, ks=1.0):
    """slLobeImageRenderer's three parts (3D lobes, polar slice, albedo) for @p models."""
    r = shadelab.slLobeImageRenderer()
    for model in models:
        if not r.AddModel(model):
            fail("unknown model " + model)
    p = r.GetLobeParameters()
    p.SetIncidenceAngle(incidence)
    p.SetDiffuseWeight(kd)
    p.SetSpecularWeight(ks)
    for key, value in (numbers or {}).items():
        if not p.SetMaterialParameter(key, value):
            fail(key)
    r.SetPanelWidth(400)
    r.SetPanelHeight(300)
    if not r.Render():
        fail("lobes " + name)
    write(rgb(r.GetImage()), name)


def albedo_table(models, roughnesses, ior, angles=4, last=75.0):
    """A markdown table: the directional albedo (k_s = 1, k_d = 0) of @p
    models at each roughness, at @p angles incidences from 0 to @p last degrees."""
    lines = []
    for alpha in roughnesses:
        t = shadelab.slAlbedoTable()
        t.SetNumberOfAngles(angles)
        t.SetMaximumIncidence(last)
        if not (t.SetMaterialParameter("roughness", alpha) and t.SetMaterialParameter("ior", ior)):
            fail("albedo parameters")
        t.Update()
        out = t.GetOutput()
        if not lines:
            degrees = out.GetColumnByName("IncidenceDegrees")
            lines.append("| model | alpha | " + " | ".join("%g°" % degrees.GetValue(i) for i in range(angles)) + " |")
            lines.append("|---|---|" + "---|" * angles)
        for model in models:
            column = out.GetColumnByName(model)
            values = " | ".join("%.4f" % column.GetValue(i) for i in range(angles))
            lines.append("| `%s` | %g | %s |" % (model, alpha, values))
    return "\n".join(lines)


def main():
    os.makedirs(OUT, exist_ok=True)
    mesh = spot_with_tangents()
    scene = base_scene()
    background = scene["background"]
    models = list(LECTURE) + [
        "lambert-normalized", "phong-normalized", "blinn-phong-normalized", "oren-nayar",
        "cook-torrance-ggx", "cook-torrance-beckmann", "ward", "ashikhmin-shirley"]
    panels = {m: cell(mesh, for_model(scene, m), m, m) for m in models}
    rows = [[panels[m] for m in models[0:3]], [panels[m] for m in models[3:7]], [panels[m] for m in models[7:11]]]
    write(tile(rows, background), "models-grid.png")
    cli_grid("models-grid-one-scene.png")

    def sweep(name, model, label, materials):
        """One row: @p model with each of @p materials (dicts of material keys) in turn."""
        row = []
        for numbers in materials:
            s = for_model(scene, model)
            s["material"].update(numbers)
            row.append(cell(mesh, s, label % tuple(numbers.values()), model))
        write(tile([row], background), name)

    # Roughness: GGX from nearly a mirror to matte.
    sweep("models-roughness.png", "cook-torrance-ggx", "GGX alpha = %g",
          [{"roughness": a} for a in (0.05, 0.15, 0.3, 0.6)])
    # Fresnel: the index of refraction sets F0; grazing light reflects more whatever it is.
    sweep("models-ior.png", "cook-torrance-ggx", "GGX ior = %g", [{"ior": n} for n in (1.2, 1.5, 3.0, 10.0)])
    # Anisotropy: Ward with the pair swapped, and equal.
    sweep("models-anisotropy.png", "ward", "Ward %g x %g",
          [{"roughnessX": x, "roughnessY": y} for x, y in ((0.1, 0.5), (0.5, 0.1), (0.25, 0.25))])

    # Blinn-Phong with the exponent of the same width, n = 2 / alpha^2 - 2
    # (Walter et al. 2007), against the microfacet models with F0 = 0.67 (ior
    # 10, a strong reflector, so that their lobes show beside k_s = 1).
    same_width = {"shininess": 2.0 / 0.3 ** 2 - 2.0, "roughness": 0.3, "ior": 10.0}
    microfacet = ["blinn-phong-normalized", "cook-torrance-ggx", "cook-torrance-beckmann"]
    lobes("models-lobes-specular.png", microfacet, 30.0, same_width)
    lobes("models-lobes-grazing.png", microfacet, 75.0, same_width)
    lobes("models-lobes-diffuse.png", ["lambert-normalized", "oren-nayar"], 60.0, {"roughness": 0.5}, kd=1.0, ks=0.0)
    lobes("models-lobes-anisotropic.png", ["ward", "ashikhmin-shirley"], 40.0,
          {"roughnessX": 0.15, "roughnessY": 0.45, "ior": 10.0})

    # The table of docs/models.md: masking-shadowing takes energy from rough surfaces.
    print()
    print(albedo_table(["cook-torrance-ggx", "cook-torrance-beckmann"], (0.1, 0.3, 0.6, 1.0), 1.5))


if __name__ == "__main__":
    main()
