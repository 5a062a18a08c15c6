"""cmake --install into a fresh prefix, then use the installed tree alone:
a downstream CMake project that find_package(ShadeLab)s it, `import shadelab`
with Debian's python3, and the installed programs."""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

BUILD = os.environ["SHADELAB_BUILD_DIR"]
SOURCE = os.environ["SHADELAB_SOURCE_DIR"]
PYTHON_DIR = os.environ["SHADELAB_PYTHON_DIR"]
CMAKE = os.environ.get("CMAKE_COMMAND", "cmake")


def run(cmd, **kwargs):
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=600, **kwargs)
    if r.returncode != 0:
        raise AssertionError(f"{' '.join(cmd)} failed ({r.returncode}):\n{r.stdout}\n{r.stderr}")
    return r


def clean_env(**extra):
    """The environment of a user who has only the installed prefix: nothing
    that points into the build tree."""
    env = {k: v for k, v in os.environ.items()
           if k not in ("PYTHONPATH", "LD_LIBRARY_PATH") and not k.startswith("SHADELAB_")}
    env.update(extra)
    return env


class InstalledTree(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp(prefix="shadelab-install-")
        cls.prefix = os.path.join(cls.work, "prefix")
        run([CMAKE, "--install", BUILD, "--prefix", cls.prefix])

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.work, ignore_errors=True)

    def test_downstream_cmake_project(self):
        build = os.path.join(self.work, "downstream")
        run([CMAKE, "-S", os.path.join(SOURCE, "tests", "install", "downstream"), "-B", build,
             "-DCMAKE_BUILD_TYPE=Release", f"-DCMAKE_PREFIX_PATH={self.prefix}"], env=clean_env())
        run([CMAKE, "--build", build], env=clean_env())
        r = run([os.path.join(build, "downstream")], env=clean_env())
        self.assertIn("largest normal error", r.stdout)
        r = run([os.path.join(build, "downstream_core")], env=clean_env())
        self.assertIn("downstream core: face normal", r.stdout)

    def test_unknown_component_is_an_error(self):
        project = os.path.join(self.work, "bad-component")
        os.makedirs(project)
        with open(os.path.join(project, "CMakeLists.txt"), "w") as f:
            f.write("cmake_minimum_required(VERSION 3.25)\nproject(p LANGUAGES C CXX)\n"
                    "find_package(ShadeLab REQUIRED COMPONENTS Normals Shaders)\n")
        r = subprocess.run([CMAKE, "-S", project, "-B", os.path.join(project, "build"),
                            f"-DCMAKE_PREFIX_PATH={self.prefix}"],
                           capture_output=True, text=True, env=clean_env())
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("ShadeLab has no component Shaders", r.stdout + r.stderr)

    def test_import_installed_python_package(self):
        site = os.path.join(self.prefix, PYTHON_DIR)
        default_scene = os.path.join(self.prefix, "share", "shadelab", "scenes", "default.json")
        with open(default_scene) as f:
            lights = len(json.load(f)["lights"])
        code = (
            "import math, shadelab\n"
            "from vtkmodules.vtkFiltersSources import vtkSphereSource\n"
            "print(shadelab.__file__)\n"
            "s = vtkSphereSource(); s.SetThetaResolution(32); s.SetPhiResolution(16)\n"
            "f = shadelab.slPolyDataNormals(); f.SetInputConnection(s.GetOutputPort()); f.Update()\n"
            "o = f.GetOutput(); n = o.GetPointData().GetArray('Normals')\n"
            "worst = 0.0\n"
            "for i in range(o.GetNumberOfPoints()):\n"
            "    p = o.GetPoint(i); r = math.sqrt(sum(c * c for c in p))\n"
            "    d = sum(p[k] * n.GetTuple3(i)[k] for k in range(3)) / r\n"
            "    worst = max(worst, math.degrees(math.acos(min(1.0, d))))\n"
            "print('worst', worst)\n"
            "scene = shadelab.slScene()\n"
            f"assert scene.ReadFile({default_scene!r})\n"
            "print('lights', scene.GetNumberOfLights())\n")
        r = run(["/usr/bin/python3", "-c", code], env=clean_env(PYTHONPATH=site), cwd=self.work)
        lines = r.stdout.split("\n")
        self.assertEqual(lines[0], os.path.join(site, "shadelab", "__init__.py"))
        self.assertLess(float(lines[1].split()[1]), 3.0)
        self.assertEqual(lines[2], f"lights {lights}")
        # Every wrapped module the build made is in the installed package.
        built = sorted(f for f in os.listdir(os.path.join(BUILD, PYTHON_DIR, "shadelab")) if f.endswith(".so"))
        installed = sorted(f for f in os.listdir(os.path.join(site, "shadelab")) if f.endswith(".so"))
        self.assertEqual(built, installed)
        self.assertGreater(len(installed), 0)

    def test_library_search_paths_stay_in_the_prefix(self):
        # Every RUNPATH entry of every installed ELF file, $ORIGIN resolved,
        # lies inside the prefix: a path reaching outside it (to / or /tmp)
        # would load whatever library someone put there.
        checked = 0
        for folder, _, files in os.walk(self.prefix):
            for name in files:
                path = os.path.join(folder, name)
                with open(path, "rb") as f:
                    if f.read(4) != b"\x7fELF":
                        continue
                dynamic = run(["readelf", "-d", path]).stdout
                for line in dynamic.splitlines():
                    if "(RUNPATH)" in line or "(RPATH)" in line:
                        for entry in line.split("[", 1)[1].rstrip("]").split(":"):
                            if not entry:
                                continue
                            resolved = os.path.realpath(entry.replace("$ORIGIN", folder))
                            self.assertTrue(resolved.startswith(os.path.realpath(self.prefix) + os.sep)
                                            or resolved == os.path.realpath(self.prefix),
                                            f"{path}: RUNPATH {entry} resolves to {resolved}")
                checked += 1
        self.assertGreater(checked, 5)

    def test_viewer_names_no_source_tree(self):
        viewer = os.path.join(self.prefix, "bin", "shadelab-viewer")
        if not os.path.exists(viewer):
            self.skipTest("built without the viewer")
        with open(viewer, "rb") as f:
            self.assertNotIn(os.path.join(SOURCE, "data").encode(), f.read())

    def test_installed_programs_run(self):
        shadelab = os.path.join(self.prefix, "bin", "shadelab")
        share = os.path.join(self.prefix, "share", "shadelab")
        out = os.path.join(self.work, "spot.png")
        run([shadelab, "render", os.path.join(share, "meshes", "spot.obj"),
             "--scene", os.path.join(share, "scenes", "default.json"), "--size", "64x48", "-o", out],
            env=clean_env(), cwd=self.work)
        with open(out, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        if os.path.exists(os.path.join(BUILD, "bin", "shadelab-viewer")):
            viewer = os.path.join(self.prefix, "bin", "shadelab-viewer")
            shot = os.path.join(self.work, "viewer.png")
            # No mesh given: the viewer opens the installed Spot and default scene.
            run([viewer, "--screenshot", shot], env=clean_env(QT_QPA_PLATFORM="xcb"), cwd=self.work)
            self.assertTrue(os.path.getsize(shot) > 0)


if __name__ == "__main__":
    unittest.main()
