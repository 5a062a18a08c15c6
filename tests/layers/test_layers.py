"""The layers the folders stand for (docs/architecture.md):

- filters/core: VTK-free C++; no file includes a VTK header or a header of a
  VTK module, no CMake file there names VTK, and the core targets link and
  include nothing of VTK (as the build resolved them);
- filters/vtk/<Module>: VTK modules, depending only on each other and on the
  core; they include no header of plugins/;
- plugins/: the render passes, the renderers over them and the ParaView view;
- the ShadeLab dependencies declared in the vtk.module files are the graph
  below, which has no cycle.
"""
import os
import re
import unittest

SOURCE = os.environ["SHADELAB_SOURCE_DIR"]
CORE = os.path.join(SOURCE, "filters", "core")
VTK_LAYER = os.path.join(SOURCE, "filters", "vtk")
PLUGINS = os.path.join(SOURCE, "plugins")


def documented_graph():
    """Module -> the ShadeLab modules it depends on, as the paragraph "The
    same as text" of docs/architecture.md states them ("IO → Common; ...")."""
    with open(os.path.join(SOURCE, "docs", "architecture.md"), encoding="utf-8") as doc:
        text = doc.read()
    start = text.index("The same as text")
    paragraph = " ".join(text[text.index("\n", start):text.index("\n\n", start)].split())
    graph = {}
    for entry in paragraph.split(";"):
        name, deps = re.match(r"\s*(\w+) → ([\w, ]+?)\.?$", entry.split(". ")[0]).groups()
        graph[name] = set() if deps == "none" else {d.strip() for d in deps.split(",")}
    return graph


# The graph of docs/architecture.md, which the vtk.module files must declare
# (DEPENDS and PRIVATE_DEPENDS).
EXPECTED_GRAPH = documented_graph()

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.MULTILINE)
SOURCE_SUFFIXES = (".h", ".hpp", ".cxx", ".cpp", ".in", ".glsl")


def files_under(folder, suffixes):
    for root, _, names in os.walk(folder):
        for name in sorted(names):
            if name.endswith(suffixes):
                yield os.path.join(root, name)


def headers_under(folder):
    return {os.path.basename(p) for p in files_under(folder, (".h", ".hpp"))}


def read_module(path):
    """(name, set of ShadeLab dependencies) of a vtk.module file."""
    with open(path) as module:
        words = module.read().split()
    name = words[words.index("NAME") + 1]
    deps, section = set(), None
    for word in words:
        if word.isupper():
            section = word
        elif section in ("DEPENDS", "PRIVATE_DEPENDS") and word.startswith("ShadeLab::"):
            deps.add(word[len("ShadeLab::"):])
    return name[len("ShadeLab::"):], deps


def module_files():
    found = {}
    for folder in (VTK_LAYER, PLUGINS):
        for path in files_under(folder, ("vtk.module",)):
            name, deps = read_module(path)
            found[name] = (path, deps)
    return found


class CoreIsVTKFree(unittest.TestCase):
    def test_no_vtk_include(self):
        outside = (headers_under(VTK_LAYER) | headers_under(PLUGINS)) - headers_under(CORE)
        sources = list(files_under(CORE, SOURCE_SUFFIXES))
        self.assertGreater(len(sources), 20)
        for path in sources:
            with open(path, encoding="utf-8") as source:
                text = source.read()
            for _, header in INCLUDE.findall(text):
                base = os.path.basename(header)
                with self.subTest(file=os.path.relpath(path, SOURCE), include=header):
                    self.assertFalse(base.lower().startswith("vtk"), "a VTK header")
                    self.assertNotRegex(base, r"^ShadeLab\w+Module\.h$", "a VTK module's export header")
                    self.assertFalse(base in outside, "a header of the VTK layer or the plugins")

    def test_no_vtk_in_cmake(self):
        for path in files_under(CORE, ("CMakeLists.txt", ".cmake")):
            with open(path) as cmake:
                text = cmake.read()
            with self.subTest(file=os.path.relpath(path, SOURCE)):
                self.assertNotRegex(text, r"VTK::|vtk_module|find_package\(\s*VTK")

    def test_core_targets_link_and_include_no_vtk(self):
        with open(os.environ["SHADELAB_CORE_TARGETS"]) as listing:
            lines = listing.read().splitlines()
        targets = {line.split()[0] for line in lines}
        self.assertEqual(targets, {"ShadeLabCommonCore", "ShadeLabLightingCore", "ShadeLabGeometryCore"})
        for line in lines:
            target, prop, *rest = line.split(" ", 2)
            for item in filter(None, (rest[0] if rest else "").split("|")):
                with self.subTest(target=target, property=prop, item=item):
                    self.assertNotRegex(item, r"(?i)vtk", "VTK in a core target")


class ModuleGraph(unittest.TestCase):
    def test_graph_is_the_documented_one(self):
        self.assertEqual(len(EXPECTED_GRAPH), 8)
        graph = {name: deps for name, (_, deps) in module_files().items()}
        self.assertEqual(graph, EXPECTED_GRAPH)

    def test_graph_has_no_cycle(self):
        done, active = set(), set()

        def visit(name):
            self.assertNotIn(name, active, f"a cycle through ShadeLab::{name}")
            if name in done:
                return
            active.add(name)
            for dep in EXPECTED_GRAPH[name]:
                visit(dep)
            active.discard(name)
            done.add(name)

        for name in EXPECTED_GRAPH:
            visit(name)

    def test_filters_depend_on_no_plugin(self):
        modules = module_files()
        plugins = {name for name, (path, _) in modules.items() if path.startswith(PLUGINS + os.sep)}
        for name, (path, deps) in modules.items():
            if path.startswith(VTK_LAYER + os.sep):
                with self.subTest(module=name):
                    self.assertFalse(deps & plugins)
                    self.assertEqual(os.path.dirname(os.path.dirname(path)), VTK_LAYER)

    def test_filters_include_no_plugin_header(self):
        plugin_headers = headers_under(PLUGINS) - headers_under(VTK_LAYER)
        for path in files_under(VTK_LAYER, SOURCE_SUFFIXES):
            with open(path, encoding="utf-8") as source:
                text = source.read()
            for _, header in INCLUDE.findall(text):
                with self.subTest(file=os.path.relpath(path, SOURCE), include=header):
                    self.assertFalse(os.path.basename(header) in plugin_headers, "a header of the plugins")


if __name__ == "__main__":
    unittest.main()
