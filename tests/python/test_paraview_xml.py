"""The ParaView plugin's server-manager XML held to the scene format: a
property that stands for a scene key has the key's range, and its default
where it overrides a scene's material (the BRDF lobe source, which reads no
scene, keeps its own defaults, those of slBRDFLobeSource); every number
key of the material is a property of the lighting filters and of the lobe
source, documented with the key's meaning; a
list of lighting models or shading frequencies names the scene format's, in
its order (their values are the ids the filters take). Reads the XML as the
plugin's build fills it (its model menus come from LightingTables.h) and the
generated scene schema: no ParaView needed."""
import json
import os
import unittest
from xml.etree import ElementTree

PLUGIN = os.environ["SHADELAB_PARAVIEW_XML_DIR"]
SCHEMA = os.environ["SHADELAB_SCHEMA_FILE"]

# The proxies that take the material's numbers (the lighting filters' base and the lobe source).
NUMBER_PROXIES = {"LitFilter", "ShadeLabBRDFLobe"}


def material_properties(material):
    """XML property name -> scene key, for every colour ("ambient" -> "AmbientColor") and number
    ("roughnessX" -> "RoughnessX") key of the schema's material."""
    names = {}
    for key, schema in material.items():
        if "$ref" in schema or schema.get("type") == "number":
            names[key[0].upper() + key[1:] + ("Color" if "$ref" in schema else "")] = key
    return names


def properties(name):
    """(proxy, property) for every XML property called @name, in every proxy of every plugin file."""
    found = []
    for file in sorted(os.listdir(PLUGIN)):
        if file.endswith(".xml"):
            root = ElementTree.parse(os.path.join(PLUGIN, file)).getroot()
            for proxy in root.iter():
                found += [(proxy.get("name"), p) for p in proxy
                          if p.get("name") == name and p.tag.endswith("VectorProperty")]
    return found


def slug(text):
    """An enumeration entry's text as a scene-format name: "Blinn-Phong (normalized)" -> "blinn-phong-normalized"."""
    return text.lower().replace(" (normalized)", "-normalized").replace(" ", "-")


class PluginXMLTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        with open(SCHEMA) as f:
            cls.defs = json.load(f)["$defs"]

    def test_material_properties_have_the_scene_defaults_and_ranges(self):
        material = self.defs["material"]["properties"]
        for name, key in material_properties(material).items():
            found = properties(name)
            self.assertTrue(found, "no XML property " + name)
            schema = material[key]
            if schema.get("type") == "number":
                self.assertEqual({proxy for proxy, _ in found}, NUMBER_PROXIES, name)
                for proxy, prop in found:
                    self.assertEqual(prop.get("command"), "Set" + name)
                    self.assertTrue(prop.find("Documentation").text.startswith(schema["description"]), name)
            default = schema["default"] if isinstance(schema["default"], list) else [schema["default"]]
            bounds = self.defs["color"]["items"] if "$ref" in schema else schema
            for proxy, prop in found:
                with self.subTest(proxy=proxy, property=name):
                    if proxy != "ShadeLabBRDFLobe":
                        self.assertEqual([float(v) for v in prop.get("default_values").split()], default)
                    domain = prop.find("DoubleRangeDomain")
                    self.assertIsNotNone(domain, "a slider needs a range")
                    self.assertEqual({float(v) for v in domain.get("min").split()}, {float(bounds["minimum"])})
                    if "maximum" in bounds:
                        self.assertEqual({float(v) for v in domain.get("max").split()}, {float(bounds["maximum"])})

    def check_enumeration(self, property_names, names, extra=()):
        """Every property of @property_names lists @names as entries 0, 1, ... (plus @extra entries)."""
        for property_name in property_names:
            for proxy, prop in properties(property_name):
                with self.subTest(proxy=proxy, property=property_name):
                    entries = [(int(e.get("value")), e.get("text")) for e in prop.find("EnumerationDomain")]
                    listed = [(v, slug(t)) for v, t in entries if (v, t) not in extra]
                    self.assertEqual(listed, list(enumerate(names)))

    def test_model_lists_are_the_scene_models(self):
        models = self.defs["shading"]["properties"]["model"]["enum"]
        self.check_enumeration(["Model", "LightingModel"], models, extra={(-1, "From Scene")})

    def test_frequency_lists_are_the_scene_frequencies(self):
        frequencies = self.defs["shading"]["properties"]["frequency"]["enum"]
        self.check_enumeration(["ShadingFrequency"], frequencies)


if __name__ == "__main__":
    unittest.main()
