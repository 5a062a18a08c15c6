"""Keenan Crane's Spot as the Python tests light it: welded point normals
(no splitting, so the arrays line up with the file's points) and, on
request, its tangent frames (slPolyDataTangents, as `shadelab tangents`)."""
import os

import shadelab


def spot_with_normals(tangents=False):
    reader = shadelab.slMeshReader()
    reader.SetFileName(os.path.join(os.environ["SHADELAB_DATA_DIR"], "meshes", "spot.obj"))
    last = shadelab.slPolyDataNormals()
    last.SetInputConnection(reader.GetOutputPort())
    last.SplittingOff()
    if tangents:
        frames = shadelab.slPolyDataTangents()
        frames.SetInputConnection(last.GetOutputPort())
        last = frames
    last.Update()
    return last.GetOutput()
