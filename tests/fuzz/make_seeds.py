"""Writes the seed corpora of the fuzz targets (tests/fuzz/seeds/<target>/):
a few small valid files per format, so that fuzzing starts from inputs that
get past each reader's header. Run with /usr/bin/python3 (python3-vtk9);
images need oiiotool (openimageio-tools).

    /usr/bin/python3 tests/fuzz/make_seeds.py
"""
import base64
import json
import os
import shutil
import struct
import subprocess

import vtk

HERE = os.path.dirname(os.path.abspath(__file__))
SEEDS = os.path.join(HERE, "seeds")


def folder(target):
    path = os.path.join(SEEDS, target)
    os.makedirs(path, exist_ok=True)
    return path


def small_mesh(with_tcoords):
    sphere = vtk.vtkSphereSource()
    sphere.SetThetaResolution(5)
    sphere.SetPhiResolution(4)
    sphere.Update()
    mesh = sphere.GetOutput()
    if with_tcoords:
        tc = vtk.vtkTextureMapToSphere()
        tc.SetInputData(mesh)
        tc.Update()
        mesh = tc.GetOutput()
    return mesh


def write(writer, mesh, path, configure=None):
    writer.SetInputData(mesh)
    writer.SetFileName(path)
    if configure:
        configure(writer)
    writer.Write()


def mesh_seeds():
    mesh = small_mesh(True)
    d = folder("fuzz_mesh_vtp")
    write(vtk.vtkXMLPolyDataWriter(), mesh, os.path.join(d, "ascii.vtp"), lambda w: w.SetDataModeToAscii())
    write(vtk.vtkXMLPolyDataWriter(), mesh, os.path.join(d, "binary.vtp"), lambda w: w.SetDataModeToBinary())
    write(vtk.vtkXMLPolyDataWriter(), mesh, os.path.join(d, "appended.vtp"), lambda w: w.SetDataModeToAppended())
    d = folder("fuzz_mesh_vtk")
    write(vtk.vtkPolyDataWriter(), mesh, os.path.join(d, "ascii.vtk"))
    write(vtk.vtkPolyDataWriter(), mesh, os.path.join(d, "binary.vtk"), lambda w: w.SetFileTypeToBinary())
    d = folder("fuzz_mesh_ply")
    write(vtk.vtkPLYWriter(), mesh, os.path.join(d, "ascii.ply"), lambda w: w.SetFileTypeToASCII())
    write(vtk.vtkPLYWriter(), mesh, os.path.join(d, "binary.ply"), lambda w: w.SetFileTypeToBinary())
    d = folder("fuzz_mesh_stl")
    write(vtk.vtkSTLWriter(), mesh, os.path.join(d, "ascii.stl"), lambda w: w.SetFileTypeToASCII())
    write(vtk.vtkSTLWriter(), mesh, os.path.join(d, "binary.stl"), lambda w: w.SetFileTypeToBinary())
    d = folder("fuzz_mesh_obj")
    with open(os.path.join(d, "plain.obj"), "w") as f:
        f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf -4 -2 -1\n")
    with open(os.path.join(d, "full.obj"), "w") as f:
        f.write("# comment\no quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                "vn 0 0 1\ng top\nusemtl red\nf 1/1/1 2/2/1 3/3/1 4/4/1\nl 1 3\np 2\nf 1//1 3//1 \\\n 4//1\n")
    # As Blender writes it, and groups and materials as ShadeLab's parser takes them.
    with open(os.path.join(d, "blender.obj"), "w") as f:
        f.write("# Blender v2.93.0 OBJ File: ''\n# www.blender.org\nmtllib untitled.mtl\no Plane\n"
                "v -1 0 1\nv 1 0 1\nv -1 0 -1\nv 1 0 -1\nvt 1 0\nvt 0 1\nvt 0 0\nvt 1 1\nvn 0 1 0\n"
                "usemtl Material\ns off\nf 2/1/1 3/2/1 1/3/1\nf 2/1/1 4/4/1 3/2/1\n")
    with open(os.path.join(d, "groups.obj"), "w") as f:
        f.write("mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n"
                "f 1 2 3\ng a\nusemtl red\nf 1//1 3//3 4//4\ng\ng b c\nusemtl green\ns 1\nf 2 3 4\n"
                "usemtl red\no more\nf 1 2 4\n")
    d = folder("fuzz_mesh_off")
    with open(os.path.join(d, "tetra.off"), "w") as f:
        f.write("OFF\n# tetrahedron\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
    with open(os.path.join(d, "quad.off"), "w") as f:
        f.write("OFF 4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3 255 0 0\n")
    gltf_seeds()


def gltf_document(uri):
    positions = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    indices = struct.pack("<3H", 0, 1, 2) + b"\0\0"
    data = positions + indices
    buffer = {"byteLength": len(data)}
    if uri:
        buffer["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    document = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"children": [1], "translation": [1, 0, 0]}, {"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [buffer],
        "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
        ],
    }
    return document, data


def gltf_seeds():
    document, _ = gltf_document(True)
    with open(os.path.join(folder("fuzz_mesh_gltf"), "triangle.gltf"), "w") as f:
        json.dump(document, f)
    document, data = gltf_document(False)
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    body = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(data), b"BIN\0") + data
    with open(os.path.join(folder("fuzz_mesh_glb"), "triangle.glb"), "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body)


def scene_seeds():
    d = folder("fuzz_scene")
    data = os.path.join(os.path.dirname(os.path.dirname(HERE)), "data", "scenes")
    for name in ("default.json", "glow.json"):
        shutil.copy(os.path.join(data, name), d)
    d = folder("fuzz_off_parser")
    for name in os.listdir(folder("fuzz_mesh_off")):
        shutil.copy(os.path.join(folder("fuzz_mesh_off"), name), d)


def brdf_seeds():
    d = folder("fuzz_brdf_file")
    data = os.path.join(os.path.dirname(os.path.dirname(HERE)), "data", "brdf")
    for name in sorted(os.listdir(data)):
        shutil.copy(os.path.join(data, name), d)


def image_seeds():
    for ext, channels in (("png", 3), ("jpg", 3), ("hdr", 3), ("exr", 4)):
        d = folder("fuzz_image_" + ext)
        subprocess.run(["oiiotool", "--pattern", "fill:top=0.1,0.5,0.9:bottom=0.9,0.2,0.1", "8x6", str(channels),
                        "-o", os.path.join(d, "gradient." + ext)], check=True)


if __name__ == "__main__":
    mesh_seeds()
    scene_seeds()
    brdf_seeds()
    image_seeds()
