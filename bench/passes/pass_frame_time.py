"""Frame time of slLightingPass against VTK's built-in lighting, driven the
way a Python user drives them: a vtkRenderWindow per renderer,
vtkRenderWindow.Render() in a loop, the renderer's own vtkLights (no ShadeLab
scene) and each actor's vtkProperty as the material. One window draws with
VTK's lighting, the other through the pass (Phong model, Phong frequency: what
VTK itself does); frames are interleaved, a run being --frames frames of each.
Prints each run's medians and ratio, then the median and range over the runs.

    bash scripts/with-display.sh /usr/bin/python3 bench/passes/pass_frame_time.py \\
        [--runs 5] [--frames 10] [--threads N] [--triangles 2000000] [--size 1024]

--threads sets llvmpipe's rendering threads (LP_NUM_THREADS; default one per
core). Needs Debian's python3-vtk9 and ShadeLab's Python package on
PYTHONPATH (build/lib/python3/dist-packages when run from the source tree).
"""
import argparse
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
import bench_common  # noqa: E402  (bench/common)


def arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    positive = lambda text: _positive(parser, text)  # noqa: E731
    parser.add_argument("--runs", type=positive, default=5, help="runs (default 5)")
    parser.add_argument("--frames", type=positive, default=10, help="frames of each renderer per run (default 10)")
    parser.add_argument("--threads", type=positive, help="llvmpipe threads, LP_NUM_THREADS (default one per core)")
    parser.add_argument("--triangles", type=positive, default=2000000, help="about this many (default 2000000)")
    parser.add_argument("--size", type=positive, default=1024, help="window width and height (default 1024)")
    bench_common.add_machine_argument(parser)
    return parser.parse_args()


def _positive(parser, text):
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        parser.error(f"'{text}' is not a whole number of at least 1")
    return value


def lights(vtk):
    """A directional key light, a point light with distance attenuation and a
    spot light (30 degree cone, exponent 2), all white, in world space."""
    key = vtk.vtkLight()
    key.SetLightTypeToSceneLight()
    key.SetPositional(False)
    key.SetPosition(0.5, 0.5, 1.0)
    key.SetFocalPoint(0.0, 0.0, 0.0)
    point = vtk.vtkLight()
    point.SetLightTypeToSceneLight()
    point.SetPositional(True)
    point.SetPosition(2.0, 1.0, 2.0)
    point.SetFocalPoint(0.0, 0.0, 0.0)
    point.SetAttenuationValues(1.0, 0.1, 0.0)
    point.SetConeAngle(180.0)
    spot = vtk.vtkLight()
    spot.SetLightTypeToSceneLight()
    spot.SetPositional(True)
    spot.SetPosition(0.0, 2.0, 2.0)
    spot.SetFocalPoint(0.0, 1.0, 1.0)
    spot.SetConeAngle(30.0)
    spot.SetExponent(2.0)
    return [key, point, spot]


def main():
    args = arguments()
    if args.threads:
        os.environ["LP_NUM_THREADS"] = str(args.threads)  # read when the first GL context is made
    if not any(os.path.isdir(os.path.join(p, "shadelab")) for p in sys.path):
        sys.path.insert(0, os.path.join(HERE, "..", "..", "build", "lib", "python3", "dist-packages"))
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL render window)
    import vtkmodules.vtkRenderingCore as vtk
    import shadelab

    mesh = bench_common.sphere_with_normals(args.triangles)

    windows, actors = [], []
    for use_pass in (False, True):
        mapper = vtk.vtkPolyDataMapper()
        mapper.SetInputData(mesh)
        actor = vtk.vtkActor()
        actor.SetMapper(mapper)
        prop = actor.GetProperty()
        prop.SetAmbient(0.1)
        prop.SetDiffuse(0.7)
        prop.SetSpecular(0.4)
        prop.SetSpecularPower(40.0)
        prop.SetInterpolationToPhong()
        renderer = vtk.vtkRenderer()
        renderer.AddActor(actor)
        renderer.AutomaticLightCreationOff()
        for light in lights(vtk):
            renderer.AddLight(light)
        camera = renderer.GetActiveCamera()
        camera.SetPosition(0.0, 0.0, 3.2)
        camera.SetFocalPoint(0.0, 0.0, 0.0)
        renderer.ResetCameraClippingRange()
        if use_pass:
            lighting = shadelab.slLightingPass()
            lighting.SetUseSceneMaterial(False)  # the material of each actor's vtkProperty
            lighting.SetModelName("phong")
            lighting.SetFrequencyName("phong")
            renderer.SetPass(lighting)
        window = vtk.vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetMultiSamples(0)
        window.SetSize(args.size, args.size)
        window.AddRenderer(renderer)
        windows.append(window)
        actors.append(actor)

    def frame(i):
        actors[i].RotateY(0.5)  # a new view each frame
        start = time.perf_counter()
        windows[i].Render()
        windows[i].WaitForCompletion()
        return 1e3 * (time.perf_counter() - start)

    for _ in range(2):  # warm-up: meshes uploaded, shaders built
        frame(0)
        frame(1)
    gl = next((line.split(":", 1)[1].strip() for line in windows[0].ReportCapabilities().splitlines()
               if line.startswith("OpenGL renderer string")), "unknown")
    bench_common.print_machine(args)
    print(f"OpenGL: {gl}; llvmpipe threads: {os.environ.get('LP_NUM_THREADS', 'one per core (LP_NUM_THREADS unset)')}")
    print(f"mesh: {mesh.GetNumberOfPolys()} triangles, window {args.size} x {args.size}, 3 vtkLights "
          f"(directional, point, spot); {args.runs} runs of {args.frames} frames each, interleaved\n")
    print("run  VTK ms/frame  pass ms/frame  pass / VTK")
    vtk_runs, pass_runs, ratios = [], [], []
    for run in range(args.runs):
        times = ([], [])
        for _ in range(args.frames):
            for i in (0, 1):
                times[i].append(frame(i))
        vtk_runs.append(statistics.median(times[0]))
        pass_runs.append(statistics.median(times[1]))
        ratios.append(pass_runs[-1] / vtk_runs[-1])
        print(f"{run + 1:3d}  {vtk_runs[-1]:12.1f}  {pass_runs[-1]:13.1f}  {ratios[-1]:10.3f}", flush=True)
    print(f"\nVTK built-in lighting: median {statistics.median(vtk_runs):.1f} ms/frame "
          f"(runs {min(vtk_runs):.1f}-{max(vtk_runs):.1f})")
    print(f"slLightingPass:        median {statistics.median(pass_runs):.1f} ms/frame "
          f"(runs {min(pass_runs):.1f}-{max(pass_runs):.1f})")
    print(f"pass / VTK: median {statistics.median(ratios):.3f} (runs {min(ratios):.3f}-{max(ratios):.3f}); "
          f"runs above 1.05: {sum(r > 1.05 for r in ratios)}, above 1.10: {sum(r > 1.10 for r in ratios)} "
          f"of {args.runs}")


if __name__ == "__main__":
    main()
