"""The lighting bench's comparison: the same Blinn-Phong point-light equation
as slShadeLight() (ambient + diffuse + specular, attenuation min(1, 1/(c1 +
c2 d + c3 d^2)), no specular where N.L <= 0, emission added once), written
as vectorised float32 numpy over all vertices, one light at a time.

usage: /usr/bin/python3 numpy_blinn_phong.py SETUP.json
SETUP.json gives the grid size, the lights, the material, the eye and the
number of repetitions; prints the median wall-clock and CPU seconds per
evaluation, then the first vertex's radiance."""
import json
import sys
import time

import numpy as np


def grid(n):
    """The bench mesh: an n x n grid on [-1, 1]^2 at z = 0, normals +z (as vtkPlaneSource)."""
    t = np.linspace(-1.0, 1.0, n, dtype=np.float32)
    x, y = np.meshgrid(t, t)
    P = np.stack([x.ravel(), y.ravel(), np.zeros(n * n, np.float32)], axis=1)
    N = np.zeros_like(P)
    N[:, 2] = 1.0
    return P, N


def normalize(v):
    length = np.sqrt(np.einsum("ij,ij->i", v, v))[:, None]
    return np.divide(v, length, out=np.zeros_like(v), where=length > 1e-18)  # SL_TINY_LENGTH


def shade(P, N, eye, lights, m):
    f32 = np.float32
    ambient = np.zeros_like(P)
    diffuse = np.zeros_like(P)
    specular = np.zeros_like(P)
    N = normalize(N)
    V = normalize(np.asarray(eye, f32) - P)
    for light in lights:
        L = np.asarray(light["position"], f32) - P
        d = np.sqrt(np.einsum("ij,ij->i", L, L))
        L = normalize(L)
        c1, c2, c3 = light["attenuation"]
        denominator = f32(c1) + f32(c2) * d + f32(c3) * d * d
        reach = f32(light["intensity"]) * np.where(denominator > 1.0, 1.0 / denominator, f32(1.0))
        ndl = np.einsum("ij,ij->i", N, L)
        H = normalize(L + V)
        ndh = np.maximum(np.einsum("ij,ij->i", N, H), 0.0)
        spec = np.where(ndl > 0.0, np.power(ndh, f32(m["shininess"])), f32(0.0))
        ambient += reach[:, None] * (np.asarray(light["ambient"], f32) * np.asarray(m["ambient"], f32))
        diffuse += (reach * np.maximum(ndl, 0.0))[:, None] * (np.asarray(light["diffuse"], f32) * np.asarray(m["diffuse"], f32))
        specular += (reach * spec)[:, None] * (np.asarray(light["specular"], f32) * np.asarray(m["specular"], f32))
    emission = np.broadcast_to(np.asarray(m["emission"], f32), P.shape)
    return ambient, diffuse, specular, emission, ambient + diffuse + specular + emission


def main():
    setup = json.load(open(sys.argv[1]))
    P, N = grid(setup["grid"])
    times, cpu = [], []
    for _ in range(setup["repetitions"]):
        start, cpu_start = time.perf_counter(), time.process_time()
        result = shade(P, N, setup["eye"], setup["lights"], setup["material"])
        times.append(time.perf_counter() - start)
        cpu.append(time.process_time() - cpu_start)
    assert np.isfinite(result[4]).all()
    print(f"{sorted(times)[len(times) // 2]:.6f} {sorted(cpu)[len(cpu) // 2]:.6f}")
    # Radiance of the first vertex, for the bench to check agreement.
    print(" ".join(f"{v:.6g}" for v in result[4][0]))


if __name__ == "__main__":
    main()
