"""The angle between two vectors, for tests that compare normals or tangents
(tests/python under python3-vtk9, tests/paraview under pvpython)."""
import math


def angle_degrees(a, b):
    """The angle in degrees between the first three components of @a and @b."""
    dot = sum(x * y for x, y in zip(a[:3], b[:3]))
    la = math.sqrt(sum(x * x for x in a[:3]))
    lb = math.sqrt(sum(x * x for x in b[:3]))
    return math.degrees(math.acos(max(-1.0, min(1.0, dot / (la * lb)))))
