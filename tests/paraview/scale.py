"""Per-rank memory and time of Sphere -> ShadeLab Normals -> ShadeLab
Radiance, each rank generating its own piece of the sphere (docs/paraview.md,
Scale). Not a test: run by hand on an idle machine.

    mpiexec -n N pvbatch --symmetric scale.py PLUGIN RESOLUTION

RESOLUTION 2050 gives 8,396,800 triangles.
"""
import resource
import sys
import time

import paraview.simple as pvs
from paraview.simple import LoadPlugin, Sphere
from vtkmodules.vtkParallelCore import vtkMultiProcessController
LoadPlugin(sys.argv[1], remote=False)
res = int(sys.argv[2])
c = vtkMultiProcessController.GetGlobalController()
rank, ranks = c.GetLocalProcessId(), c.GetNumberOfProcesses()
sphere = Sphere(ThetaResolution=res, PhiResolution=res)
sphere.UpdatePipeline()
rss0 = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
normals = pvs.ShadeLabNormals(Input=sphere, Splitting=0)
c.Barrier()
t0 = time.time()
normals.UpdatePipeline()
c.Barrier()
t1 = time.time()
lit = pvs.ShadeLabRadiance(Input=normals)
lit.UpdatePipeline()
c.Barrier()
t2 = time.time()
cells = normals.GetClientSideObject().GetOutput().GetNumberOfCells()
rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
print("ranks %d rank %d: %d triangles, normals %.2f s, radiance %.2f s, max RSS %.0f MB (after source %.0f MB)" % (
    ranks, rank, cells, t1 - t0, t2 - t1, rss / 1024.0, rss0 / 1024.0), flush=True)
