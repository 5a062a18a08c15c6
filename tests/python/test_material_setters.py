"""The material's number setters held to the material table: one plain
setter per number key of the scene format (read from the generated JSON
schema) on slLitFilter and slBRDFLobeSource, clamped to the key's range,
with its default; and each reaching its formula (those of slAlbedoTable
by key), against values computed here in closed form or through the
scene-file route."""
import json
import math
import os
import sys
import tempfile
import unittest

import shadelab

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from spot_mesh import spot_with_normals  # noqa: E402
from vtk_errors import update_error  # noqa: E402

DATA = os.environ["SHADELAB_DATA_DIR"]
SCHEMA = os.environ["SHADELAB_SCHEMA_FILE"]
SCENE = os.path.join(DATA, "scenes", "default.json")

# A model that reads each number key (the test names the model a new key needs).
MODEL_READING = {"shininess": "blinn-phong", "roughness": "cook-torrance-ggx", "roughnessX": "ward",
                 "roughnessY": "ward", "ior": "cook-torrance-ggx"}


def number_keys():
    """key -> schema of every number key of the scene format's material."""
    with open(SCHEMA) as f:
        material = json.load(f)["$defs"]["material"]["properties"]
    return {key: s for key, s in material.items() if s.get("type") == "number"}


def setter(key):
    """"roughnessX" -> "RoughnessX", the setter's and getter's suffix."""
    return key[0].upper() + key[1:]


MESH = spot_with_normals(tangents=True)


def radiance(configure):
    f = shadelab.slRadianceFilter()
    f.SetInputData(MESH)
    configure(f)
    error = update_error(f)
    array = f.GetOutput().GetPointData().GetArray("Radiance")
    return error, [array.GetTuple3(i) for i in range(array.GetNumberOfTuples())] if array else None


def lobe_points(source):
    """(direction, r) of every lobe point with r > 0: the surface is r(w_o) w_o."""
    source.Update()
    out = source.GetOutput(0)
    values = out.GetPointData().GetArray("BRDF")
    points = []
    for i in range(out.GetNumberOfPoints()):
        p, r = out.GetPoint(i), values.GetValue(i)
        if r > 1e-6:
            points.append(([c / r for c in p], r))
    return points


class MaterialSetterTest(unittest.TestCase):
    def test_every_number_key_has_a_clamped_setter_with_its_default(self):
        """Plain Set<Key>/Get<Key> (what ParaView reaches) on the lighting filters and the lobe source."""
        keys = number_keys()
        self.assertEqual(set(keys), set(MODEL_READING), "a new number key needs a model that reads it here")
        for obj in (shadelab.slRadianceFilter(), shadelab.slBRDFLobeSource()):
            lit = isinstance(obj, shadelab.slLitFilter)
            for key, schema in keys.items():
                name = setter(key)
                with self.subTest(cls=obj.GetClassName(), key=key):
                    if lit:  # vtkSetClampMacro
                        self.assertEqual(getattr(obj, "Get" + name + "MinValue")(), schema["minimum"])
                        self.assertEqual(getattr(obj, "Get" + name + "MaxValue")(), schema["maximum"])
                    if lit or key != "shininess":  # the lobe source's own n is 20
                        self.assertAlmostEqual(getattr(obj, "Get" + name)(), schema["default"], places=6)
                    getattr(obj, "Set" + name)(schema["maximum"] + 1.0)
                    self.assertEqual(getattr(obj, "Get" + name)(), schema["maximum"])
                    getattr(obj, "Set" + name)(schema["minimum"] - 1.0)
                    self.assertEqual(getattr(obj, "Get" + name)(), schema["minimum"])
                    if not lit:
                        self.assertEqual(obj.GetMaterialParameter(key), schema["minimum"])

    def test_print_names_each_number_by_its_setter(self):
        """PrintSelf lists each number as Shininess, RoughnessX, ... with the value set."""
        # Values in every key's range, exact in float, so printed as set.
        wanted = {key: 1.5 if key == "ior" else 0.25 + i / 16.0 for i, key in enumerate(number_keys())}
        for make in (shadelab.slRadianceFilter, shadelab.slBRDFLobeSource, shadelab.slAlbedoTable):
            obj = make()
            for key, value in wanted.items():
                if hasattr(obj, "Set" + setter(key)):
                    getattr(obj, "Set" + setter(key))(value)
                else:
                    obj.SetMaterialParameter(key, value)
            text = str(obj)
            for key, value in wanted.items():
                with self.subTest(cls=obj.GetClassName(), key=key):
                    self.assertIn("  %s: %g\n" % (setter(key), value), text)

    def test_setter_equals_the_scene_key(self):
        """OverrideMaterial with one number set equals a scene file holding it, and differs from the default."""
        for key, schema in number_keys().items():
            value = schema["minimum"] + 0.37 * (min(schema["maximum"], 64.0) - schema["minimum"])
            model = MODEL_READING[key]
            with self.subTest(key=key), tempfile.TemporaryDirectory() as folder:
                path = os.path.join(folder, "scene.json")
                with open(SCENE) as f:
                    scene = json.load(f)
                scene["shading"] = dict(scene.get("shading", {}), model=model)
                scene["material"] = {key: value}  # the others at their defaults, as the filter's are
                with open(path, "w") as f:
                    json.dump(scene, f)
                error, by_file = radiance(lambda f: f.SetSceneFileName(path))
                self.assertEqual(error, "")

                def override(f):
                    f.SetSceneFileName(SCENE)
                    f.SetModel(MODELS.index(model))
                    f.OverrideMaterialOn()
                    getattr(f, "Set" + setter(key))(value)
                error, by_setter = radiance(override)
                self.assertEqual(error, "")
                self.assertEqual(by_setter, by_file)
                _, default = radiance(lambda f: (f.SetSceneFileName(SCENE), f.SetModel(MODELS.index(model)),
                                                 f.OverrideMaterialOn()))
                self.assertNotEqual(by_setter, default)

    def test_nan_is_an_error_naming_the_key(self):
        for key in number_keys():
            with self.subTest(key=key):
                def configure(f):
                    f.OverrideMaterialOn()
                    getattr(f, "Set" + setter(key))(float("nan"))
                error, out = radiance(configure)
                self.assertIn("material." + key, error)
                self.assertIsNone(out)

    def test_lobe_ggx_at_normal_incidence(self):
        """Cook-Torrance GGX with L = V = N: f_r = F0 / (4 pi alpha^2), F0 = ((ior - 1) / (ior + 1))^2."""
        for alpha, ior in ((0.2, 1.5), (0.5, 3.0)):
            lobe = shadelab.slBRDFLobeSource()
            lobe.SetModel(MODELS.index("cook-torrance-ggx"))
            lobe.SetIncidenceAngle(0.0)
            lobe.SetRoughness(alpha)
            lobe.SetIor(ior)
            f0 = ((ior - 1.0) / (ior + 1.0)) ** 2
            peak = max(r for _, r in lobe_points(lobe))
            self.assertAlmostEqual(peak / (f0 / (4.0 * math.pi * alpha * alpha)), 1.0, delta=1e-4)

    def test_lobe_ward_is_wide_along_the_tangent_x(self):
        """Ward with L = N, V at angle t from N in the x-z plane: H is t/2 from N along x, so
        f_r = exp(-tan^2(t/2) / ax^2) / (4 pi ax ay sqrt(cos t)); along y, ax and ay swap places."""
        ax, ay = 0.2, 0.5
        lobe = shadelab.slBRDFLobeSource()
        lobe.SetModel(MODELS.index("ward"))
        lobe.SetIncidenceAngle(0.0)
        lobe.SetRoughnessX(ax)
        lobe.SetRoughnessY(ay)
        checked = 0
        for (x, y, z), r in lobe_points(lobe):
            t = math.acos(max(-1.0, min(1.0, z)))
            if z < 0.2:
                continue
            along = ax if abs(y) < 1e-6 else ay if abs(x) < 1e-6 else None
            if along is None:
                continue
            expected = math.exp(-math.tan(t / 2) ** 2 / along ** 2) / (4 * math.pi * ax * ay * math.sqrt(z))
            self.assertAlmostEqual(r / expected, 1.0, delta=1e-4, msg=f"direction {(x, y, z)}")
            checked += 1
        self.assertGreater(checked, 20)

    def test_albedo_table_oren_nayar_and_fresnel(self):
        """Oren-Nayar's albedo at normal incidence is A = 1 - 0.5 s^2 / (s^2 + 0.33) (its B term
        vanishes with L = N); GGX's at low roughness scales with F0 of the index of refraction."""
        def column(table, model):
            table.Update()
            return table.GetOutput().GetColumnByName(model).GetValue(0)
        table = shadelab.slAlbedoTable()
        table.SetNumberOfAngles(2)
        for sigma in (0.0, 0.5, 1.0):
            table.SetMaterialParameter("roughness", sigma)
            s2 = sigma * sigma
            self.assertAlmostEqual(column(table, "oren-nayar"), 1.0 - 0.5 * s2 / (s2 + 0.33), delta=1e-4)
        table.SetMaterialParameter("roughness", 0.02)
        albedo = {}
        for ior in (1.5, 3.0):
            table.SetMaterialParameter("ior", ior)
            albedo[ior] = column(table, "cook-torrance-ggx")
        f0 = {ior: ((ior - 1.0) / (ior + 1.0)) ** 2 for ior in albedo}
        self.assertAlmostEqual(albedo[3.0] / albedo[1.5], f0[3.0] / f0[1.5], delta=1e-2 * f0[3.0] / f0[1.5])


def model_names():
    with open(SCHEMA) as f:
        return json.load(f)["$defs"]["shading"]["properties"]["model"]["enum"]


MODELS = model_names()

if __name__ == "__main__":
    unittest.main()
