"""Large meshes for the app tests, written with numpy: a bumpy grid of
2 (n-1)^2 triangles."""


def write_grid_ply(path, n):
    """A bumpy (n-1) x (n-1) grid of 2 (n-1)^2 triangles with texture coordinates, binary PLY."""
    import numpy as np
    u = np.linspace(0.0, 1.0, n)
    x, y = np.meshgrid(u, u)
    z = 0.05 * np.sin(12 * x) * np.cos(9 * y)
    vertices = np.stack([x.ravel(), y.ravel(), z.ravel(), x.ravel(), y.ravel()], 1).astype("<f4")
    i, j = np.meshgrid(np.arange(n - 1), np.arange(n - 1))
    a = (j * n + i).ravel()
    faces = np.zeros(2 * len(a), dtype=[("n", "u1"), ("i", "<i4", (3,))])
    faces["n"] = 3
    faces["i"] = np.concatenate([np.stack([a, a + 1, a + n + 1], 1), np.stack([a, a + n + 1, a + n], 1)])
    with open(path, "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
                 "property float z\nproperty float u\nproperty float v\nelement face %d\n"
                 "property list uchar int vertex_indices\nend_header\n" % (len(vertices), len(faces))).encode())
        f.write(vertices.tobytes())
        f.write(faces.tobytes())


def write_grid_obj(path, n):
    """A bumpy (n-1) x (n-1) grid of 2 (n-1)^2 triangles with texture coordinates, as OBJ text."""
    import numpy as np
    u = np.linspace(0.0, 1.0, n)
    x, y = np.meshgrid(u, u)
    z = 0.05 * np.sin(12 * x) * np.cos(9 * y)
    with open(path, "w") as f:
        f.write("".join("v %.6f %.6f %.6f\n" % p for p in zip(x.ravel(), y.ravel(), z.ravel())))
        f.write("".join("vt %.6f %.6f\n" % t for t in zip(x.ravel(), y.ravel())))
        f.write("".join("f %d/%d %d/%d %d/%d\nf %d/%d %d/%d %d/%d\n" % (a, a, a + 1, a + 1, a + n + 1, a + n + 1,
                                                                         a, a, a + n + 1, a + n + 1, a + n, a + n)
                        for a in (j * n + i + 1 for j in range(n - 1) for i in range(n - 1))))
