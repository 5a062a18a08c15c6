"""Per-rank memory and time of Sphere -> ShadeLab Normals -> ShadeLab
Radiance, each rank generating its own piece of the sphere (docs/paraview.md,
Scale). Not a test: run by hand on an idle machine.

    mpiexec -n N pvbatch --symmetric scale.py PLUGIN RESOLUTION [THREADS]

RESOLUTION 2050 gives 8,396,800 triangles. THREADS: vtkSMPTools threads per
rank (default: VTK's choice, every core).
"""
import resource
import sys
import time

import paraview.simple as pvs
from paraview.simple import LoadPlugin, Sphere
from vtkmodules.vtkCommonCore import vtkSMPTools
from vtkmodules.vtkParallelCore import vtkMultiProcessController
LoadPlugin(sys.argv[1], remote=False)
res = int(sys.argv[2])
if len(sys.argv) > 3 and int(sys.argv[3]) > 0:
    vtkSMPTools.Initialize(int(sys.argv[3]))
c = vtkMultiProcessController.GetGlobalController()
rank, ranks = c.GetLocalProcessId(), c.GetNumberOfProcesses()
sphere = Sphere(ThetaResolution=res, PhiResolution=res)
sphere.UpdatePipeline()
rss0 = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
normals = pvs.ShadeLabNormals(Input=sphere, Splitting=0)


def timed(update):
    """Wall time of @update on every rank: from a barrier to the barrier after."""
    c.Barrier()
    start = time.time()
    update()
    c.Barrier()
    return time.time() - start


# On several ranks ShadeLab Normals asks for one ghost level more than the
# sphere was made with, so its first update also runs the source again
# (vtkSphereSource makes its piece without ghost cells); the second, after a
# change that re-executes only the filter, is the filter alone.
first = timed(normals.UpdatePipeline)
normals.FeatureAngle = 31
alone = timed(normals.UpdatePipeline)
lit = pvs.ShadeLabRadiance(Input=normals)
radiance = timed(lit.UpdatePipeline)
cells = normals.GetClientSideObject().GetOutput().GetNumberOfCells()
rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
print("ranks %d rank %d: %d triangles, %s threads of %s, normals %.2f s (filter alone %.2f s), radiance %.2f s, "
      "max RSS %.0f MB (after source %.0f MB)" % (
          ranks, rank, cells, vtkSMPTools.GetEstimatedNumberOfThreads(), vtkSMPTools.GetBackend(), first, alone,
          radiance, rss / 1024.0, rss0 / 1024.0), flush=True)
