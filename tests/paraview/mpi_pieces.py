"""One run of the MPI comparison (tests/paraview/run-tests.sh runs it on 1, 2
and 3 ranks):

    mpiexec -n N pvbatch --symmetric mpi_pieces.py PLUGIN MESH.vtp OUT.pvtp

reads MESH.vtp, spreads its cells over the ranks with D3 (ghost cells only on
request), and writes ShadeLab Normals -> Tangents -> Radiance as OUT.pvtp
(inline binary pieces, one per rank). ParaView's default request of one
ghost level for unstructured pipelines is turned off on every rank, so the
filters get ghost cells only when they ask for them themselves.
"""
import sys

import paraview.simple as pvs
from paraview.modules.vtkRemotingCore import vtkProcessModule
from paraview.simple import D3, ExtractSurface, LoadPlugin, SaveData, XMLPolyDataReader

plugin, mesh, out = sys.argv[1:4]
vtkProcessModule.SetDefaultMinimumGhostLevelsToRequestForUnstructuredPipelines(0)
LoadPlugin(plugin, remote=False)

reader = XMLPolyDataReader(FileName=[mesh])
spread = D3(Input=reader)
surface = ExtractSurface(Input=spread)
normals = pvs.ShadeLabNormals(Input=surface)
tangents = pvs.ShadeLabTangents(Input=normals)
radiance = pvs.ShadeLabRadiance(Input=tangents)
# ParaView's parallel XML writers ask for one ghost level by default
# (GhostLevel 1); then the filters keep their ghost cells for the writer.
SaveData(out, proxy=radiance, DataMode="Binary", GhostLevel=0)
