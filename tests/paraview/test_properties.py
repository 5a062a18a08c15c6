"""The plugin's proxies as a ParaView user meets them, in pvpython:

- every numeric property agrees with the VTK class it drives: its XML
  default is the default of a freshly made object of the class, and its
  range domain is the range the class's setter clamps to (a bound the
  setter does not clamp to is no bound of the domain, and the other way
  round). Both come from the compiled class itself: a new instance's
  PrintSelf, and the values the setter keeps when the property is pushed
  out of range; nothing is read from the headers;
- every property a user sees has a tooltip (Documentation);
- the diffuse colour array of ShadeLab Radiance and of the Monte Carlo
  reference is chosen from the input's RGB and RGBA point arrays, stays
  empty (no array) unless chosen, and colours the lighting equation;
- a state file saved with the filters and the ShadeLab Render View loads
  back with the same property values and the same result;
- a Python trace of building the pipeline replays to the same result.

    pvpython test_properties.py PLUGIN MESH.vtp WORK_DIR
"""
import json
import math
import os
import subprocess
import sys
import unittest

from paraview import servermanager, smtrace
import paraview.simple as pvs
from paraview.simple import LoadPlugin, XMLPolyDataReader

PLUGIN, MESH, WORK = sys.argv[1:4]
del sys.argv[1:4]
LoadPlugin(PLUGIN, remote=False)

GROUPS = ("filters", "sources")


def plugin_proxies():
    """(group, name) of every proxy the plugin adds to a menu."""
    definitions = servermanager.ProxyManager().GetProxyDefinitionManager()
    found = []
    for group in GROUPS:
        iterator = definitions.NewSingleGroupIterator(group)
        iterator.GoToFirstItem()
        while not iterator.IsDoneWithTraversal():
            if iterator.GetProxyName().startswith("ShadeLab"):
                found.append((group, iterator.GetProxyName()))
            iterator.GoToNextItem()
    return found


def print_self(vtk_object):
    """Member name -> the text PrintSelf gives for it."""
    members = {}
    for line in str(vtk_object).splitlines():
        name, sep, value = line.strip().partition(": ")
        if sep:
            members.setdefault(name, value.strip())
    return members


def number(text):
    """The first token of a PrintSelf value as a number, or None (a name such as "angle")."""
    try:
        return float(text.split()[0])
    except (ValueError, IndexError):
        return None


def settable_properties(proxy):
    """(name, property) of every user property of @proxy that calls a Set<Member> command; on a
    proxy just made, a property's elements are its XML defaults."""
    iterator = proxy.NewPropertyIterator()
    iterator.Begin()
    found = []
    while not iterator.IsAtEnd():
        prop = iterator.GetProperty()
        command = prop.GetCommand() or ""
        if command.startswith("Set") and not prop.GetInformationOnly() and not prop.GetIsInternal():
            found.append((iterator.GetKey(), prop))
        iterator.Next()
    return found


def range_domain(prop):
    for cls in ("vtkSMDoubleRangeDomain", "vtkSMIntRangeDomain"):
        domain = prop.FindDomain(cls)
        if domain is not None:
            return domain
    return None


def new_proxy(group, name):
    proxy = servermanager.ProxyManager().NewProxy(group, name)
    proxy.UpdateVTKObjects()
    return proxy


class PropertiesAgreeWithTheClasses(unittest.TestCase):
    def test_defaults_are_the_classes_defaults(self):
        for group, name in plugin_proxies():
            proxy = new_proxy(group, name)
            # A new object of the proxy's class, untouched by ParaView.
            fresh = print_self(proxy.GetClientSideObject().NewInstance())
            for key, prop in settable_properties(proxy):
                member = prop.GetCommand()[3:]
                if not prop.IsA("vtkSMIntVectorProperty") and not prop.IsA("vtkSMDoubleVectorProperty"):
                    continue
                with self.subTest(proxy=name, property=key):
                    self.assertIn(member, fresh, "PrintSelf of %s does not show %s" % (name, member))
                    defaults = [prop.GetElement(i) for i in range(prop.GetNumberOfElements())]
                    cpp = fresh[member].split()
                    if number(fresh[member]) is None:
                        # An enumeration printed by name: the default entry's text.
                        enum = prop.FindDomain("vtkSMEnumerationDomain")
                        entry = [enum.GetEntryText(i) for i in range(enum.GetNumberOfEntries())
                                 if enum.GetEntryValue(i) == defaults[0]]
                        self.assertEqual([e.lower() for e in entry], [fresh[member].lower()])
                        continue
                    for xml, value in zip(defaults, cpp):
                        self.assertTrue(math.isclose(xml, float(value), rel_tol=1e-5),
                                        "XML default %s, the class's %s" % (defaults, fresh[member]))

    def test_ranges_are_the_setters_clamps(self):
        for group, name in plugin_proxies():
            proxy = new_proxy(group, name)
            for key, prop in settable_properties(proxy):
                member = prop.GetCommand()[3:]
                is_int = prop.IsA("vtkSMIntVectorProperty")
                if not is_int and not prop.IsA("vtkSMDoubleVectorProperty"):
                    continue
                if prop.GetNumberOfElements() != 1 or prop.FindDomain("vtkSMEnumerationDomain") is not None \
                        or prop.FindDomain("vtkSMBooleanDomain") is not None:
                    continue
                domain = range_domain(prop)
                default = prop.GetElement(0)
                for side in ("min", "max"):
                    with self.subTest(proxy=name, property=key, bound=side):
                        exists = domain is not None and (
                            domain.GetMinimumExists(0) if side == "min" else domain.GetMaximumExists(0))
                        bound = (domain.GetMinimum(0) if side == "min" else domain.GetMaximum(0)) if exists else None
                        # Beyond the bound (or, without one, far from the default), within int's range.
                        reference = bound if exists else default
                        step = 10 * (abs(reference) + 1)
                        probe = reference - step if side == "min" else reference + step
                        if is_int:
                            probe = int(max(-2**30, min(2**30, probe)))
                        prop.SetElement(0, probe)
                        proxy.UpdateVTKObjects()
                        kept = number(print_self(proxy.GetClientSideObject())[member])
                        if exists:
                            self.assertTrue(math.isclose(kept, bound, rel_tol=1e-5),
                                            "the domain's %s is %s; the setter keeps %s" % (side, bound, kept))
                        else:
                            self.assertTrue(math.isclose(kept, probe, rel_tol=1e-5),
                                            "no %s in the domain, but the setter clamps %s to %s" % (side, probe, kept))
                prop.SetElement(0, default)
                proxy.UpdateVTKObjects()

    def test_every_property_has_a_tooltip(self):
        for group, name in plugin_proxies() + [("views", "ShadeLabRenderView")]:
            proxy = servermanager.ProxyManager().NewProxy(group, name)
            for key, prop in settable_properties(proxy):
                if group == "views" and key not in ("SceneFileName", "LightingModel", "ShadingFrequency",
                                                    "UseSceneMaterial"):
                    continue  # ParaView's own render-view properties
                if prop.GetPanelVisibility() == "never":
                    continue
                with self.subTest(proxy=name, property=key):
                    doc = prop.GetDocumentation()
                    self.assertIsNotNone(doc, "no Documentation")
                    self.assertTrue((doc.GetDescription() or "").strip(), "empty Documentation")


def with_colours():
    """The test mesh with point and cell normals and three extra point arrays: RGB, RGBA and one
    component."""
    normals = pvs.ShadeLabNormals(Input=XMLPolyDataReader(FileName=[MESH]), ComputeCellNormals=1)
    rgb = pvs.Calculator(Input=normals, ResultArrayName="Rgb", Function="0.5*iHat+0.25*jHat+1*kHat")
    scalar = pvs.Calculator(Input=rgb, ResultArrayName="Grey", Function="0.5")
    rgba = pvs.PythonCalculator(Input=scalar, ArrayName="Rgba",
                                Expression="numpy.tile([1.0, 0.5, 0.25, 1.0], (len(inputs[0].Points), 1))")
    return rgba


# The filters that take a diffuse colour array, the properties that make them quick, and the array
# that holds the discrete lighting equation (the reference's own estimate has no ambient term).
COLOURED_FILTERS = (
    (pvs.ShadeLabRadiance, {}, "Radiance"),
    (pvs.ShadeLabMonteCarloReference, dict(SamplesPerPoint=1), "DiscreteRadiance"),
)


class ArraySelection(unittest.TestCase):
    def test_diffuse_colour_arrays_offered_and_applied(self):
        source = with_colours()
        source.UpdatePipeline()  # the list is of the arrays the input has
        for make, quick, _ in COLOURED_FILTERS:
            with self.subTest(filter=make.__name__):
                radiance = make(Input=source, **quick)
                prop = radiance.GetProperty("DiffuseColorArrayName")
                # No array until one is chosen: the default is the empty choice, not the first array.
                self.assertEqual(radiance.DiffuseColorArray, "")
                self.assertEqual(radiance.DiffuseTexture, "")
                # Every point array of the input (ParaView 5.11's domain cannot ask for 3 or 4
                # components), and the empty choice; no cell array.
                points = servermanager.Fetch(source).GetPointData()
                arrays = [points.GetArrayName(i) for i in range(points.GetNumberOfArrays())]
                self.assertIn("Rgba", arrays)
                self.assertEqual(sorted(prop.Available), sorted([""] + arrays))

    def test_chosen_array_multiplies_the_diffuse_colour(self):
        source = with_colours()
        # Only k_a, which the array multiplies as it does k_d: with Rgb = (0.5, 0.25, 1) every point's
        # red is half the plain one's, its green a quarter, its blue the same.
        settings = dict(OverrideMaterial=1, AmbientColor=[0.2, 0.2, 0.2], DiffuseColor=[0, 0, 0],
                        SpecularColor=[0, 0, 0], EmissionColor=[0, 0, 0])
        for make, quick, name in COLOURED_FILTERS:
            with self.subTest(filter=make.__name__):
                plain = make(Input=source, **quick, **settings)
                coloured = make(Input=source, DiffuseColorArray="Rgb", **quick, **settings)
                a = servermanager.Fetch(plain).GetPointData().GetArray(name)
                b = servermanager.Fetch(coloured).GetPointData().GetArray(name)
                self.assertAlmostEqual(b.GetRange(0)[0], 0.5 * a.GetRange(0)[0], places=6)
                self.assertAlmostEqual(b.GetRange(1)[0], 0.25 * a.GetRange(1)[0], places=6)
                self.assertAlmostEqual(b.GetRange(2)[0], a.GetRange(2)[0], places=6)
                # A one-component array is offered but is no colour: the filter reports it, no output.
                grey = make(Input=source, DiffuseColorArray="Grey", **quick)
                self.assertEqual(servermanager.Fetch(grey).GetNumberOfPoints(), 0)


def radiance_of(proxy):
    proxy.UpdatePipeline()
    return servermanager.Fetch(proxy).GetPointData().GetArray("Radiance").GetRange(0)


class StateAndTrace(unittest.TestCase):
    def build(self, traced=False):
        """Reader -> Normals -> Radiance, each filter made and then its properties set, as the GUI
        does (and, @traced, traced as the GUI's Apply traces them)."""
        def apply(proxy, **values):
            item = smtrace.PropertiesModified(proxy) if traced else None
            for key, value in values.items():
                setattr(proxy, key, value)
            if item:
                item.finalize()
            return proxy

        reader = XMLPolyDataReader(registrationName="spot.vtp", FileName=[MESH])
        normals = apply(pvs.ShadeLabNormals(registrationName="normals", Input=reader),
                        Weighting="Area", FeatureAngle=45)
        return apply(pvs.ShadeLabRadiance(registrationName="lit", Input=normals),
                     LightingModel="Cook-Torrance GGX", OverrideMaterial=1, Roughness=0.6,
                     DiffuseColor=[0.3, 0.6, 0.9], SpecularColor=[0.1, 0.2, 0.3])

    def test_state_file_round_trip(self):
        lit = self.build()
        view = pvs.CreateView("ShadeLabRenderView", ShadingFrequency="Gouraud", LightingModel="Phong")
        pvs.Show(lit, view)
        expected = radiance_of(lit)
        state = os.path.join(WORK, "shadelab.pvsm")
        pvs.SaveState(state)
        # Loaded in a new session, as a user opens a state file.
        script = os.path.join(WORK, "load_state.py")
        with open(script, "w") as f:
            f.write("""import json, sys
from paraview import servermanager
from paraview.simple import *
LoadPlugin(%r, remote=False)
LoadState(%r)
lit = FindSource("lit")
lit.UpdatePipeline()
views = [v for v in GetViews() if v.GetXMLName() == "ShadeLabRenderView"]
print(json.dumps(dict(model=lit.LightingModel.GetData(), roughness=lit.Roughness, diffuse=list(lit.DiffuseColor),
    weighting=FindSource("normals").Weighting.GetData(), angle=FindSource("normals").FeatureAngle,
    radiance=servermanager.Fetch(lit).GetPointData().GetArray("Radiance").GetRange(0),
    views=[(v.ShadingFrequency.GetData(), v.LightingModel.GetData()) for v in views])))
""" % (PLUGIN, state))
        run = subprocess.run(["pvpython", script], capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        out = run.stdout
        loaded = json.loads(out.strip().splitlines()[-1])
        self.assertEqual(loaded["model"], "Cook-Torrance GGX")
        self.assertAlmostEqual(loaded["roughness"], 0.6)
        self.assertEqual(loaded["diffuse"], [0.3, 0.6, 0.9])
        self.assertEqual((loaded["weighting"], loaded["angle"]), ("Area", 45))
        self.assertEqual(tuple(loaded["radiance"]), expected)
        self.assertEqual(loaded["views"], [["Gouraud", "Phong"]])
        pvs.Delete(view)

    def test_trace_replays(self):
        smtrace.start_trace()
        lit = self.build(traced=True)
        expected = radiance_of(lit)
        trace = smtrace.stop_trace()
        self.assertIn("ShadeLabRadiance(", trace)
        self.assertIn("Roughness = 0.6", trace)
        script = os.path.join(WORK, "trace.py")
        out = os.path.join(WORK, "traced.vtp")
        with open(script, "w") as f:
            f.write("from paraview.simple import *\n")
            f.write("LoadPlugin(%r, remote=False)\n" % PLUGIN)
            f.write(trace)
            f.write("\nSaveData(%r, proxy=FindSource('lit'), DataMode='Ascii')\n" % out)
        subprocess.run(["pvpython", script], check=True)
        replay = XMLPolyDataReader(FileName=[out])
        replay.UpdatePipeline()
        got = servermanager.Fetch(replay).GetPointData().GetArray("Radiance").GetRange(0)
        for g, e in zip(got, expected):
            self.assertAlmostEqual(g, e, places=5)


if __name__ == "__main__":
    unittest.main()
