"""The bad-input cases: (name, arguments, input files, exit status, stderr).

Arguments and messages use paths relative to the case's folder, where the
input files are written and every out.* argument already exists with other
content. Each case expects exactly one line on stderr."""
import json
import struct

from inputs import (QUAD_OBJ, TETRA_OFF, THREE_LIGHTS, dds_volume, exr, exr_attribute, exr_scanlines, glb, gltf, legacy_vtk, light_types,
                    lighting_models, obj, ply_ascii, ply_binary, ply_header, png, stl_binary, tiff_tiled, vtp,
                    vtp_appended_base64_header, vtp_compressed_header)


EXTRACT_SURFACE = "extract its surface first (vtkDataSetSurfaceFilter, or ParaView's Extract Surface) and save it as .vtp"


def mesh_case(name, file_name, data, message, status=1):
    """shadelab normals on one mesh file."""
    return (name, ["normals", file_name, "-o", "out.vtp"], {file_name: data}, status,
            "shadelab normals: " + file_name + ": " + message + "\n" if message is not None else None)


def scene_case(name, data, message, status=1):
    """shadelab cosine with a bad scene (the mesh is fine)."""
    return (name, ["cosine", "m.off", "--scene", "s.json", "-o", "out.vtp"], {"m.off": TETRA_OFF, "s.json": data},
            status, "shadelab cosine: s.json: " + message + "\n" if message is not None else None)


def image_case(name, file_name, data, message, status=1):
    """shadelab light with a bad diffuse texture."""
    return (name, ["light", "q.obj", "--diffuse-texture", file_name, "-o", "out.vtp"],
            {"q.obj": QUAD_OBJ, file_name: data}, status, message)


def cli_case(name, args, message, status=2, files=None):
    """A bad command line on good inputs."""
    inputs = {"m.off": TETRA_OFF, "three.json": THREE_LIGHTS}
    inputs.update(files or {})
    return (name, args, inputs, status, message)


BRDF_SHADER = b"::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec3(1.0); }\n::end shader\n"


def brdf_case(name, data, message, extra=()):
    """shadelab lobe --brdf b.brdf with a bad file or --param (None: no file)."""
    return (name, ["lobe", "--brdf", "b.brdf", *extra, "-o", "out.png"], {} if data is None else {"b.brdf": data}, 1,
            "shadelab lobe: " + message + "\n")


def ply_ascii_attributes(second_row):
    """An ASCII PLY tetrahedron with point normals and u, v; line 16 is
    @second_row (vertex 1)."""
    header = ply_header(b"ascii", 4, 4).replace(
        b"property float z\n", b"property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
        b"property float u\nproperty float v\n")
    return (header + b"0 0 0 -1 -1 -1 0 0\n" + second_row + b"0 1 0 0 1 0 0 1\n0 0 1 0 0 1 1 1\n"
            b"3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")


def legacy_vtk_binary(point_data):
    """A binary legacy VTK triangle followed by POINT_DATA 3 and @point_data."""
    return (b"# vtk DataFile Version 3.0\nbad input\nBINARY\nDATASET POLYDATA\nPOINTS 3 float\n" +
            struct.pack(">9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + b"\nPOLYGONS 1 4\n" + struct.pack(">4i", 3, 0, 1, 2) +
            b"\nPOINT_DATA 3\n" + point_data)


def half_exr(*values):
    """An uncompressed OpenEXR 1 pixel wide, a row (top first) per 16-bit
    half @values in its channel Y, with the offset table."""
    start = len(exr_scanlines(len(values))) + 8 * len(values)
    return exr_scanlines(len(values), tail=b"".join(struct.pack("<Q", start + 10 * y) for y in range(len(values))) +
                         b"".join(struct.pack("<iiH", y, 2, v) for y, v in enumerate(values)))


CASES = [
    # OBJ
    mesh_case("obj index beyond vertices", "a.obj", obj(b"f 1 2 9\n"), 'line 4: vertex index 9 is out of range [1, 3]'),
    mesh_case("obj index zero", "a.obj", obj(b"f 0 1 2\n"), 'line 4: vertex index 0 is invalid (OBJ indices start at 1)'),
    mesh_case("obj negative index before first", "a.obj", obj(b"f -1 -2 -4\n"), 'line 4: vertex index -4 reaches before the first vertex (3 precede the line)'),
    mesh_case("obj huge index", "a.obj", obj(b"f 1 2 99999999999999999999\n"), 'line 4: vertex index 99999999999999999999 is out of range [1, 3]'),
    mesh_case("obj int overflow index", "a.obj", obj(b"f 1 2 4294967297\n"), 'line 4: vertex index 4294967297 is out of range [1, 3]'),
    mesh_case("obj comment ending in a backslash does not hide a face", "a.obj",
              b"# a comment \\\nf 1 2 3\n", 'line 2: vertex index 1 is out of range [1, 0]'),
    # VTK's reader continues a face after a backslash behind any white space.
    mesh_case("obj face continued after a vertical tab", "a.obj", obj(b"f 1 2 \x0b\\\n3 9\n"),
              'line 5: vertex index 9 is out of range [1, 3]'),
    mesh_case("obj nan coordinate", "a.obj", b"v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", 'line 1: v coordinate "nan" is not a finite number'),
    mesh_case("obj inf coordinate", "a.obj", b"v 0 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n", 'line 2: v coordinate "inf" is not a finite number'),
    mesh_case("obj overflowing coordinate", "a.obj", b"v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n", 'line 2: v coordinate "1e999" is not a finite number'),
    mesh_case("obj two coordinates", "a.obj", b"v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", 'line 1: v needs at least 3 values, it has 2'),
    mesh_case("obj word as coordinate", "a.obj", b"v 0 zero 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", 'line 1: v "zero" is not a number'),
    mesh_case("obj escape bytes as coordinate", "a.obj", b"v 0 \x1b[31mred 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", 'line 1: v "\\x1B[31mred" is not a number'),
    # vtkOBJReader reads values into floats and two of every vt line: a value beyond float range or a
    # vt of one value left values unset
    mesh_case("obj coordinate beyond float", "a.obj", b"v 1e39 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
              'line 1: v coordinate "1e39" is beyond the range of float'),
    mesh_case("obj vt of one value", "a.obj", obj(b"f 1/1 2/2 3/3\n", b"vt 0.5\nvt 0.5\nvt 0.5\n"),
              'line 4: vt needs at least 2 values, it has 1'),
    # vtkOBJReader attaches the listed normals as they are when faces name the same v and vn index
    mesh_case("obj fewer normals than points", "a.obj",
              b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\nf 1//1 2//2 3//3\nf 1//1 3//3 2//2\n",
              'point array "Normals" has 3 tuples for 4 points'),
    mesh_case("obj vt index beyond", "a.obj", obj(b"f 1/1 2/2 3/3\n", b"vt 0 0\nvt 1 0\n"), 'line 6: texture coordinate index 3 is out of range [1, 2]'),
    mesh_case("obj vn index beyond", "a.obj", obj(b"f 1//1 2//2 3//1\n", b"vn 0 0 1\n"), 'line 5: normal index 2 is out of range [1, 1]'),
    mesh_case("obj nan normal", "a.obj", obj(b"f 1//1 2//1 3//1\n", b"vn nan 0 1\n"), 'line 4: vn coordinate "nan" is not a finite number'),
    mesh_case("obj index not a number", "a.obj", obj(b"f 1 2 three\n"), 'line 4: vertex index "three" is not an integer'),
    mesh_case("obj four-part index", "a.obj", obj(b"f 1/1/1/1 2 3\n"), 'line 4: "1/1/1/1" is not an index triple'),
    # VTK's reader would take the -1 after the slash as a texture coordinate.
    mesh_case("obj slash before a space", "a.obj", obj(b"f 1 2/ -1\n"), 'line 4: "2/" ends in a slash, without the index after it'),
    mesh_case("obj slash ending a line", "a.obj", obj(b"f 1 2 3//\n", b"vn 0 0 1\n"), 'line 5: "3//" ends in a slash, without the index after it'),
    mesh_case("obj long material name", "a.obj", obj(b"f 1 2 3\n", b"usemtl " + b"m" * 100 + b"\n"),
              "line 4: usemtl name of 100 bytes is longer than the 99 that VTK's OBJ reader holds"),
    mesh_case("obj line index beyond", "a.obj", obj(b"l 1 5\n"), 'line 4: vertex index 5 is out of range [1, 3]'),
    mesh_case("obj point index beyond", "a.obj", obj(b"p 4\n"), 'line 4: vertex index 4 is out of range [1, 3]'),
    # ShadeLab's own parser reads faces with l and p elements, and faces of several forms: it declines
    # these, so the check names the line.
    mesh_case("obj line index beyond beside a face", "a.obj", obj(b"f 1 2 3\nl 1 5\n"), 'line 5: vertex index 5 is out of range [1, 3]'),
    mesh_case("obj nan normal beside a face without one", "a.obj", obj(b"f 1//1 2//1 3//1\nf 1 2 3\n", b"vn nan 0 1\n"),
              'line 4: vn coordinate "nan" is not a finite number'),
    mesh_case("obj face of two corners", "a.obj", obj(b"f 1 2\n"), 'line 4: f needs at least 3 vertices, it has 2'),
    mesh_case("obj no faces", "a.obj", obj(b""), 'no polygons among its 0 cells'),
    mesh_case("obj empty", "a.obj", b"", 'the file is empty'),
    mesh_case("obj binary garbage", "a.obj", bytes(range(256)), 'Line longer than 262144:'),
    # PLY
    mesh_case("ply truncated ascii", "a.ply", ply_ascii(b"")[:-6], 'line 12: the file ends before element "vertex" row 3 of 3'),
    mesh_case("ply face list beyond its values", "a.ply", ply_ascii(b"5 0 1 2\n"), 'line 13 (element "face" row 1 of 1): fewer values than "vertex_indices" needs'),
    # VTK reads only "vertex" and "face", in file order: an element it skips must not come first.
    mesh_case("ply element read as faces", "a.ply",
              b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
              b"element edge 1\nproperty list uchar int vertex_pair\nelement face 1\n"
              b"property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n2 0 900\n3 0 1 2\n",
              'element "edge" comes before "face": VTK\'s PLY reader would read its rows as "face"'),
    mesh_case("ply face texcoords before vertex", "a.ply",
              b"ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
              b"property list uchar float texcoord\nelement vertex 3\nproperty float x\nproperty float y\n"
              b"property float z\nend_header\n3 0 1 2 6 0 0 1 0 0 1\n0 0 0\n1 0 0\n0 1 0\n",
              'element "face" has texture coordinates and comes before "vertex": VTK\'s PLY reader needs the '
              'vertices first'),
    # vtkPLYReader keeps a face's corner count in a byte: 300 corners came back as 44.
    mesh_case("ply face beyond 255 corners", "a.ply", ply_ascii(b"300 " + b"0 1 2 " * 100 + b"\n"),
              'line 13 (element "face" row 1 of 1): 300 corners; VTK\'s PLY reader takes at most 255'),
    mesh_case("ply face index beyond", "a.ply", ply_ascii(b"3 0 1 7\n"), 'line 13 (element "face" row 1 of 1): vertex index 7 is out of range [0, 3)'),
    mesh_case("ply negative face index", "a.ply", ply_ascii(b"3 0 -1 2\n"), 'line 13 (element "face" row 1 of 1): vertex index -1 is out of range [0, 3)'),
    mesh_case("ply missing face row", "a.ply", ply_ascii(b"3 0 1 2\n", faces=2), 'line 14: the file ends before element "face" row 2 of 2'),
    mesh_case("ply word as coordinate", "a.ply", ply_header(b"ascii", 3, 0) + b"0 0 0\n1 x 0\n0 1 0\n", 'line 11 (element "vertex" row 2 of 3): "x" is not a number'),
    mesh_case("ply nan coordinate", "a.ply", ply_ascii(b"3 0 1 2\n").replace(b"1 0 0\n", b"nan 0 0\n"), 'point 1 has a NaN or infinite coordinate'),
    mesh_case("ply huge vertex count", "a.ply", ply_ascii(b"3 0 1 2\n", vertices=10**12), 'line 14: the file ends before element "vertex" row 5 of 1000000000000'),
    mesh_case("ply huge binary face count", "a.ply", ply_binary([0, 1, 2], faces=2 * 10**9), 'the file ends within element "face" row 2 of 2000000000'),
    mesh_case("ply truncated binary", "a.ply", ply_binary([0, 1, 2], cut=3), 'the file ends within element "face" row 1 of 1'),
    mesh_case("ply binary face index beyond", "a.ply", ply_binary([0, 1, 3]), 'element "face" row 1 of 1: vertex index 3 is out of range [0, 3)'),
    mesh_case("ply binary negative index", "a.ply", ply_binary([0, -5, 2]), 'element "face" row 1 of 1: vertex index -5 is out of range [0, 3)'),
    mesh_case("ply no end_header", "a.ply", b"ply\nformat ascii 1.0\nelement vertex 0\n", 'line 3: the header has no end_header'),
    mesh_case("ply unknown format", "a.ply", b"ply\nformat nonsense 1.0\nend_header\n", 'line 2: unknown format "nonsense"'),
    mesh_case("ply unknown type", "a.ply", b"ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n0\n",
              'line 4: unknown property type "quad"'),
    mesh_case("ply float list count", "a.ply",
              ply_header(b"ascii", 3, 1, b"property list float int vertex_indices") + b"0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
              'line 8: list count type "float" is not an integer type'),
    mesh_case("ply bad magic with escapes", "a.ply", b"\x1b]0;owned\x07\nformat ascii 1.0\n", 'line 1: expected "ply", found "\\x1B]0;owned\\x07"'),
    mesh_case("ply negative element count", "a.ply", b"ply\nformat ascii 1.0\nelement vertex -3\nend_header\n", 'line 3: element needs a name and a count, found "element vertex -3"'),
    mesh_case("ply empty", "a.ply", b"", 'the file is empty'),
    # found by fuzzing: a NUL byte cut an ASCII row short for vtkPLY, which then parsed a null word
    mesh_case("ply nul byte in ascii row", "a.ply", ply_ascii(b"3 0 1 2\n").replace(b"1 0 0\n", b"1 \x000 0\n"),
              'line 11 (element "vertex" row 2 of 3): a NUL byte'),
    # found by fuzzing: vtkPLY splits rows at spaces, tabs and carriage returns only; a vertical tab
    # joined two indices into one word and it read a word past the row's end
    mesh_case("ply vertical tab in ascii row", "a.ply", ply_ascii(b"3 0 1\x0b2\n"),
              'line 13 (element "face" row 1 of 1): "1\\x0B2" is not a number'),
    mesh_case("ply form feed in ascii row", "a.ply", ply_ascii(b"3 0 1 2\n").replace(b"1 0 0\n", b"1 0\x0c0\n"),
              'line 11 (element "vertex" row 2 of 3): "0\\x0C0" is not a number'),
    # vtkPLY renames the rest of a header line from its first "vertex_index" to "vertex_indices":
    # here the count goes, and it read the count from a word the line does not have
    mesh_case("ply element name starting vertex_index", "a.ply",
              ply_ascii(b"3 0 1 2\n5\n").replace(b"end_header", b"element vertex_indexQ 1\nproperty float a\nend_header"),
              'line 9: expected 3 words, found "element vertex_indexQ 1"'),
    # vtkPolyData builds no cell types around a polygon of fewer than 3 points: the VTP writer crashed
    mesh_case("ply face of two points", "a.ply", ply_ascii(b"3 0 1 2\n2 0 1\n", faces=2),
              'polygon 1 has fewer than 3 points (2)'),
    mesh_case("ply vertex without y", "a.ply",
              ply_ascii(b"3 0 1 2\n").replace(b"property float y\n", b"property float x\n"),
              'the header needs an element "vertex" with properties x, y, z and an element "face"'),
    # found by fuzzing: vtkPLYReader crashed in find_element on a file without a vertex element
    mesh_case("ply last row without a newline", "a.ply", ply_ascii(b"3 0 1 2"),
              'line 13 (element "face" row 1 of 1): no newline at the end of the row'),
    mesh_case("ply row longer than VTK's line", "a.ply", ply_ascii(b"3 0 1 2" + b" " * 4000 + b"\n"),
              'line 13 (element "face" row 1 of 1): longer than 4000 characters'),
    mesh_case("ply blank line in the header", "a.ply", ply_ascii(b"3 0 1 2\n").replace(b"element face", b"\nelement face"),
              'line 7: a blank line in the header'),
    # ShadeLab's own binary parser takes this one; no face, no connectivity.
    mesh_case("ply binary without faces", "a.ply", ply_header(b"binary_little_endian", 3, 0) + struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0),
              'no polygons among its 0 cells'),
    mesh_case("ply element without properties", "a.ply",
              ply_header(b"binary_little_endian", 3, 0).replace(b"property list uchar int vertex_indices\n", b"") +
              struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0), 'line 7: element "face" has no properties'),
    mesh_case("ply without vertex element", "a.ply",
              b"ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n3 0 1 2\n",
              'the header needs an element "vertex" with properties x, y, z and an element "face"'),
    # found by fuzzing: control bytes in a header line corrupted vtkPLY's element table
    mesh_case("ply control bytes in header", "a.ply", b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\x01\x00v\n",
              'line 4: a control byte in the header: "property float x\\x01\\x00v"'),
    mesh_case("ply property with extra words", "a.ply", b"ply\nformat ascii 1.0\nelement vertex 3 extra\n",
              'line 3: expected 3 words, found "element vertex 3 extra"'),
    # found by fuzzing: a second "vertex" element was read over the first one's arrays (crash in vtkCell)
    mesh_case("ply element named twice", "a.ply",
              ply_ascii(b"3 0 1 2\n").replace(b"element face 1\n", b"element vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n")
              .replace(b"3 0 1 2\n", b"0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
              'the header has two elements named "vertex"'),
    # found by fuzzing: vtkPLYReader freed an uninitialised pointer
    mesh_case("ply face without index list", "a.ply",
              ply_header(b"ascii", 3, 1, b"property list uchar int corners") + b"0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
              'element "face" has no list property "vertex_indices" (or "vertex_index")'),
    # STL
    mesh_case("stl truncated binary", "a.stl", stl_binary(32, cut=21 * 50 + 7), 'truncated binary STL: its header announces 32 triangles (1684 bytes), the file has 627 bytes'),
    mesh_case("stl header only with count", "a.stl", stl_binary(0, declared=5), 'truncated binary STL: its header announces 5 triangles (334 bytes), the file has 84 bytes'),
    mesh_case("stl shorter than header", "a.stl", b"\x80\x81\x82" * 10, 'binary STL shorter than its 84-byte header (30 bytes)'),
    mesh_case("stl ascii garbage", "a.stl", b"solid x\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0\n", 'STLReader: error while reading file a.stl at line 4: Parse error reading STL vertex'),
    mesh_case("stl empty", "a.stl", b"", 'the file is empty'),
    # VTP
    mesh_case("vtp index beyond points", "a.vtp", vtp(b"0 1 7"), 'polygon 0 names point 7, but the mesh has 3 points (0 to 2)'),
    mesh_case("vtp negative index", "a.vtp", vtp(b"0 -1 2"), 'polygon 0 names point -1, but the mesh has 3 points (0 to 2)'),
    mesh_case("vtp offsets beyond ids", "a.vtp", vtp(b"0 1 2", offsets=b"5"),
              'Cannot read cell connectivity from Polys in piece 0 because the "connectivity" array is not long enough.'),
    mesh_case("vtp huge point count", "a.vtp", vtp(b"0 1 2", points=10**12), 'NumberOfPoints=1000000000000 is more than a file of 516 bytes can hold'),
    mesh_case("vtp malformed xml", "a.vtp", b"<VTKFile type=\"PolyData\"><PolyData>",
              'Error parsing XML in stream at line 1, column 35, byte index 35: no element found'),
    mesh_case("vtp empty", "a.vtp", b"", 'the file is empty'),
    # found by fuzzing: a compression header VTK allocated for (8.6 GB)
    mesh_case("vtp compressed header block count", "a.vtp", vtp_compressed_header(2000000000),
              'DataArray "Points": its compression header declares 2000000000 blocks of 32768 bytes, more than a file '
              'of 412 bytes can hold'),
    mesh_case("vtp last block beyond the block size", "a.vtp", vtp_compressed_header(1, last=2147483744),
              'DataArray "Points": its compression header\'s last block of 2147483744 bytes is larger than its '
              'block size of 32768'),
    # VTK's data size wraps around below zero blocks and it reads block 0 (a crash).
    mesh_case("vtp compressed header without blocks but a last block", "a.vtp", vtp_compressed_header(0, last=480),
              'DataArray "Points": its compression header declares no blocks but a last block of 480 bytes'),
    mesh_case("vtp compressed block beyond the file", "a.vtp", vtp_compressed_header(1, sizes=(2000000000,)),
              'DataArray "Points": its compression header gives block 0 2000000000 compressed bytes, more than the '
              'file\'s %d' % len(vtp_compressed_header(1, sizes=(2000000000,)))),
    # vtkBase64InputStream decodes padding and bytes outside the alphabet into a header.
    mesh_case("vtp appended data without its marker", "a.vtp",
              vtp_appended_base64_header(1).replace(b"\n_", b"\n"),
              'the AppendedData element\'s data does not start with "_"'),
    # VTK's reader would read the offsets from the "z", four characters early.
    mesh_case("vtp appended data with a byte before its marker", "a.vtp",
              vtp_appended_base64_header(1).replace(b"\n_", b"\nz  _"),
              'the AppendedData element\'s data does not start with "_"'),
    mesh_case("vtp base64 header with padding inside", "a.vtp", vtp_appended_base64_header(0, b"AQAA=AAAAAAAAAAA"),
              'DataArray "Points": its compression header\'s 1 block sizes are not 16 bytes of base64'),
    mesh_case("vtp appended base64 header block count", "a.vtp", vtp_appended_base64_header(1429727086),
              'DataArray "Points": its compression header declares 1429727086 blocks of 32768 bytes, more than a '
              'file of 465 bytes can hold'),
    # VTK reads an array with an offset from the appended data whatever its
    # format says (found by fuzzing: "for-at" for "format", 2.2 GB allocated).
    mesh_case("vtp appended array without a format", "a.vtp",
              vtp_appended_base64_header(1429727086).replace(b' format="appended"', b''),
              'DataArray "Points": its compression header declares 1429727086 blocks of 32768 bytes, more than a '
              'file of 447 bytes can hold'),
    # expat reads attributes in single quotes, with white space around "=",
    # and with character references decoded: so must the check.
    mesh_case("vtp count in single quotes", "a.vtp",
              vtp(b"0 1 2", points=10**12).replace(b'NumberOfPoints="1000000000000"', b"NumberOfPoints = '1000000000000'"),
              'NumberOfPoints=1000000000000 is more than a file of 518 bytes can hold'),
    mesh_case("vtp count written with a character reference", "a.vtp",
              vtp(b"0 1 2", points=10**12).replace(b'"1000000000000"', b'"&#49;000000000000"'),
              'NumberOfPoints=1000000000000 is more than a file of 520 bytes can hold'),
    # A comment may hold quotes and '<': the counts after it are still read.
    mesh_case("vtp count after a comment with a quote", "a.vtp",
              vtp(b"0 1 2", points=10**12).replace(b"<PolyData>", b"<!-- 5 < 6 \" --><PolyData>"),
              'NumberOfPoints=1000000000000 is more than a file of 532 bytes can hold'),
    # Markup inside a comment is not markup: neither a tag that would end
    # the markup early nor one that would lend the file its attributes.
    mesh_case("vtp count after a comment naming the appended data", "a.vtp",
              vtp(b"0 1 2", points=10**12).replace(b"<PolyData>", b"<!-- <AppendedData> --><PolyData>"),
              'NumberOfPoints=1000000000000 is more than a file of 539 bytes can hold'),
    mesh_case("vtp compressed header after a comment naming the file", "a.vtp",
              vtp_compressed_header(2000000000).replace(b"<VTKFile", b"<!-- <VTKFile> -->\n<VTKFile", 1),
              'DataArray "Points": its compression header declares 2000000000 blocks of 32768 bytes, more than a file '
              'of 431 bytes can hold'),
    # Each '<' starts a tag that ends at the last byte: the check reads on
    # from a tag's end, not from its next byte (which took minutes here).
    mesh_case("vtp a megabyte of tag starts closed once", "a.vtp", b"<" * 1000000 + b">",
              'Error parsing XML in stream at line 1, column 1, byte index 1: not well-formed (invalid token)'),
    # Each '&' of a value looks for its ';': once for all of them, not once
    # each (eight megabytes took minutes).
    mesh_case("vtp eight megabytes of ampersands in a value", "a.vtp", b'<VTKFile a="' + b"&" * 8000000 + b'">',
              'Error parsing XML in stream at line 1, column 13, byte index 13: not well-formed (invalid token)'),
    mesh_case("vtp appended offset after white space", "a.vtp",
              vtp_appended_base64_header(1429727086).replace(b' offset="0"', b'\n offset = "4"').replace(b"\n_", b"\n_AAAA"),
              'DataArray "Points": its compression header declares 1429727086 blocks of 32768 bytes, more than a '
              'file of 472 bytes can hold'),
    mesh_case("vtp negative appended offset", "a.vtp",
              vtp_appended_base64_header(1).replace(b' offset="0"', b' offset="-12"'),
              'DataArray "Points": its offset -12 is negative'),
    mesh_case("vtp entity declaration", "a.vtp",
              vtp(b"0 1 2").replace(b'<VTKFile', b'<!DOCTYPE VTKFile [<!ENTITY n "1000000000000">]>\n<VTKFile')
              .replace(b'NumberOfPoints="3"', b'NumberOfPoints="&n;"'),
              "an entity declaration, which VTK's XML files do not have"),
    # VTK reads a negative count as it is: it read the data as far before the
    # array as the count was below zero (a crash), compressed or not.
    mesh_case("vtp negative point count", "a.vtp",
              vtp_appended_base64_header(0, struct.pack("<I9f", 36, 0, 0, 0, 1, 0, 0, 0, 1, 0))
              .replace(b'base64"', b'raw"').replace(b' compressor="vtkZLibDataCompressor"', b'')
              .replace(b'NumberOfPoints="3"', b'NumberOfPoints="-1"'),
              'NumberOfPoints=-1 is negative'),
    # An LZ4 block of 36 literal bytes.
    mesh_case("vtp negative point count with lz4", "a.vtp",
              vtp_appended_base64_header(0, struct.pack("<4I2B9f", 1, 32768, 36, 38, 0xF0, 21, 0, 0, 0, 1, 0, 0, 0, 1, 0))
              .replace(b'base64"', b'raw"').replace(b"vtkZLib", b"vtkLZ4")
              .replace(b'NumberOfPoints="3"', b'NumberOfPoints="-1"'),
              'NumberOfPoints=-1 is negative'),
    # zlib.compress of the three points.
    mesh_case("vtp negative point count with zlib", "a.vtp",
              vtp_appended_base64_header(0, struct.pack("<4I", 1, 32768, 36, 16) + b"x\x9cc`@\x06\r\xf6\x0cX\xf8\x00\x14\x8a\x01\x7f")
              .replace(b'base64"', b'raw"').replace(b'NumberOfPoints="3"', b'NumberOfPoints=" -1"'),
              'NumberOfPoints=-1 is negative'),
    mesh_case("vtp negative vertex count", "a.vtp", vtp(b"0 1 2").replace(b'NumberOfVerts="0"', b'NumberOfVerts="-2"'),
              'NumberOfVerts=-2 is negative'),
    # VTK 9.1 crashed reading a String array's appended data.
    mesh_case("vtp string point data in appended data", "a.vtp",
              vtp_appended_base64_header(0, struct.pack("<I9f", 36, 0, 0, 0, 1, 0, 0, 0, 1, 0) * 2)
              .replace(b'base64"', b'raw"').replace(b' compressor="vtkZLibDataCompressor"', b'')
              .replace(b"<Points>", b'<PointData><DataArray type="String" Name="s" NumberOfComponents="3" '
                       b'format="appended" offset="40"/></PointData>\n<Points>'),
              'DataArray "s": type "String" is not one of the numeric types VTK writes (Int8, UInt8, Int16, UInt16, '
              'Int32, UInt32, Int64, UInt64, Float32, Float64)'),
    mesh_case("vtp array without a type", "a.vtp", vtp(b"0 1 2").replace(b'type="Float32"', b'Name="Points"'),
              'DataArray "Points": it has no type (one of the numeric types VTK writes: Int8, UInt8, Int16, UInt16, '
              'Int32, UInt32, Int64, UInt64, Float32, Float64)'),
    # VTK sizes a tuple buffer by the component count: -1 threw, 0 read one component.
    mesh_case("vtp negative component count", "a.vtp",
              vtp(b"0 1 2").replace(b'NumberOfComponents="3"', b'Name="Points" NumberOfComponents="-1"'),
              'DataArray "Points": NumberOfComponents=-1 is less than 1'),
    mesh_case("vtp zero component count", "a.vtp",
              vtp(b"0 1 2").replace(b'NumberOfComponents="3"', b'Name="Points" NumberOfComponents="0"'),
              'DataArray "Points": NumberOfComponents=0 is less than 1'),
    mesh_case("vtp huge component count", "a.vtp",
              vtp(b"0 1 2").replace(b'NumberOfComponents="3"', b'Name="Points" NumberOfComponents="3000000000"'),
              'DataArray "Points": NumberOfComponents=3000000000 is more than a file of 527 bytes can hold'),
    # VTK's compressors name no array ("Zlib error while uncompressing data.").
    mesh_case("vtp lz4 blocks under a zlib header", "a.vtp",
              vtp_appended_base64_header(0, struct.pack("<4I2B9f", 1, 32768, 36, 38, 0xF0, 21, 0, 0, 0, 1, 0, 0, 0, 1, 0))
              .replace(b'base64"', b'raw"'),
              'DataArray "Points": its block 0 of 1 does not uncompress with vtkZLibDataCompressor, the file\'s '
              'compressor'),
    # VTK reads data as far as the file goes and reports a short read, if at
    # all, for a later array ("Error reading uncompressed binary data header").
    mesh_case("vtp appended data ending within an array's data", "a.vtp",
              vtp_appended_base64_header(0, struct.pack("<I4f", 36, 0, 0, 0, 1))
              .replace(b'base64"', b'raw"').replace(b' compressor="vtkZLibDataCompressor"', b'')
              .split(b"\n</AppendedData>")[0],
              'DataArray "Points": its header declares 36 bytes of data, the file holds 16 after it'),
    mesh_case("vtp appended data ending before an array's header", "a.vtp",
              vtp_appended_base64_header(0, b"").replace(b'base64"', b'raw"')
              .replace(b' compressor="vtkZLibDataCompressor"', b'').split(b"\n</AppendedData>")[0],
              'DataArray "Points": the file ends within its header (0 of 4 bytes)'),
    mesh_case("vtp appended data ending within compressed data", "a.vtp",
              vtp_appended_base64_header(0, struct.pack("<4I", 1, 32768, 36, 16) + b"x\x9cc`@\x06")
              .replace(b'base64"', b'raw"').split(b"\n</AppendedData>")[0],
              'DataArray "Points": its compression header declares 16 bytes of compressed data, the file holds 6 '
              'after it'),
    # legacy VTK
    mesh_case("vtk polygon of one point", "a.vtk", legacy_vtk(b"POLYGONS 2 6\n3 0 1 2\n1 0\n"),
              'polygon 1 has fewer than 3 points (1)'),
    mesh_case("vtk index beyond points", "a.vtk", legacy_vtk(b"POLYGONS 1 4\n3 0 1 7\n"), 'polygon 0 names point 7, but the mesh has 3 points (0 to 2)'),
    mesh_case("vtk negative index", "a.vtk", legacy_vtk(b"POLYGONS 1 4\n3 0 -2 1\n"), 'polygon 0 names point -2, but the mesh has 3 points (0 to 2)'),
    # vtkDataReader loops for ever when a numeric METADATA key's values end early.
    mesh_case("vtk metadata values end early", "a.vtk",
              legacy_vtk(b"METADATA\nINFORMATION 1\nNAME L2_NORM_RANGE LOCATION vtkDataArray\nDATA 4 0.5 0.5\n\n"
                         b"POLYGONS 1 4\n3 0 1 2\n"),
              'line 10: METADATA key vtkDataArray::L2_NORM_RANGE: DATA declares 4 values and its line holds 2'),
    mesh_case("vtk metadata with a nul byte", "a.vtk",
              b"# vtk DataFile Version 3.0\nbad input\nBINARY\nDATASET POLYDATA\nPOINTS 3 float\n" + bytes(36) +
              b"\nMETADATA\nINFORMATION 1\nNAME X LOCATION Y\nDATA 1\n\0\0\0\nPOLYGONS 1 4\n" +
              struct.pack(">4i", 3, 0, 1, 2) + b"\n",
              'line 11: a NUL byte within a METADATA block'),
    # vtkDataReader compares METADATA keywords case-insensitively and splits
    # them at any white space; a DATA value it cannot read makes it loop for ever.
    mesh_case("vtk metadata keywords in lower case and tabs", "a.vtk",
              legacy_vtk(b"METADATA\ninformation\t2\nNAME COMPONENT_RANGE LOCATION vtkDataArray\nDATA\tx\n\n"
                         b"POLYGONS 1 4\n3 0 1 2\n"),
              'line 10: METADATA key vtkDataArray::COMPONENT_RANGE: DATA must give its length and its values'),
    mesh_case("vtk metadata data line indented", "a.vtk",
              legacy_vtk(b"METADATA\nINFORMATION\t1\nNAME L2_NORM_RANGE LOCATION vtkDataArray\n DATA 2 nan 1\n\n"
                         b"POLYGONS 1 4\n3 0 1 2\n"),
              'line 10: METADATA key vtkDataArray::L2_NORM_RANGE: DATA declares 2 values and its line holds 2, not all numbers'),
    # VTK allocates components times tuples (a product that can wrap to 0, and
    # crash it) and per-tuple buffers of the component count.
    mesh_case("vtk field array size overflowing", "a.vtk",
              legacy_vtk(b"FIELD f 1\na 16777216 1099511627776 float\n0\nPOLYGONS 1 4\n3 0 1 2\n"),
              'line 8: FIELD array "a": 16777216 components, more than the file\'s 157 bytes could hold'),
    mesh_case("vtk field array of many components and no tuples", "a.vtk",
              legacy_vtk(b"FIELD f 1\na 268435456 0 float\nPOLYGONS 1 4\n3 0 1 2\n"),
              'line 8: FIELD array "a": 268435456 components, more than the file\'s 144 bytes could hold'),
    mesh_case("vtk field array of more values than the file holds", "a.vtk",
              legacy_vtk(b"FIELD f 1\na 4 1099511627776 float\n0\nPOLYGONS 1 4\n3 0 1 2\n"),
              'line 8: FIELD array "a": 1099511627776 tuples of 4 components, more values than the file\'s 150 bytes could hold'),
    # VTK reads the file type as one word: the rest of line 3 is content.
    mesh_case("vtk content after the file type", "a.vtk",
              b"# vtk DataFile Version 3.0\nt\nASCII DATASET POLYDATA POINTS 3 float\nPOLYGONS 1 4\n3 0 1 2\n",
              'line 4: POINTS: "POLYGONS" is not a number'),
    # VTK skips a binary keyword line's rest with getline(line, 256): a longer
    # one fails its stream, and the values are never read.
    mesh_case("vtk binary points after a long keyword line", "a.vtk",
              b"# vtk DataFile Version 3.0\nt\nBINARY\nDATASET POLYDATA\nPOINTS 3 float" + b" " * 300 + b"\n" +
              struct.pack(">9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + b"\nPOLYGONS 1 4\n" + struct.pack(">4i", 3, 0, 1, 2) + b"\n",
              'line 5: POINTS: keyword line longer than the 255 bytes VTK reads before binary data'),
    mesh_case("vtk binary polygons after a long keyword line", "a.vtk",
              b"# vtk DataFile Version 3.0\nt\nBINARY\nDATASET POLYDATA\nPOINTS 3 float\n" +
              struct.pack(">9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + b"\nPOLYGONS 1 4" + b" " * 300 + b"\n" +
              struct.pack(">4i", 3, 0, 1, 2) + b"\n",
              'line 7: POLYGONS: keyword line longer than the 255 bytes VTK reads before binary data'),
    # vtkDataReader::DecodeString reads past the end of a name shorter than 3
    # characters holding a '%'.
    mesh_case("vtk short name with a percent sign", "a.vtk",
              legacy_vtk(b"POLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\nSCALARS % float\nLOOKUP_TABLE default\n0 0 0\n"),
              'line 10: SCALARS: name "%" holds a % in fewer than 3 characters, which VTK decodes by reading past its end'),
    # vtkDataReader reads a legacy cell list into int with operator>>: it
    # crashed on "3.0" (count 3, then ".0"); "1e23" was no number of ids.
    mesh_case("vtk cell count with a decimal point", "a.vtk", legacy_vtk(b"POLYGONS 1 4\n3.0 0 1 2\n"),
              'line 8: POLYGONS: "3.0" is not an integer VTK reads as int'),
    mesh_case("vtk cell id in exponent form", "a.vtk", legacy_vtk(b"POLYGONS 1 4\n3 0 1 1e23\n"),
              'line 8: POLYGONS: "1e23" is not an integer VTK reads as int'),
    mesh_case("vtk cell id beyond int", "a.vtk", legacy_vtk(b"POLYGONS 1 4\n3 0 1 4294967298\n"),
              'line 8: POLYGONS: "4294967298" is not an integer VTK reads as int'),
    mesh_case("vtk dataset type with a tail", "a.vtk", legacy_vtk(b"POLYGONS 1 4\n3 0 1 2\n", dataset=b"POLYDATAx"),
              'line 4: dataset type "POLYDATAX" is not POLYDATA, though VTK would read it as POLYDATA'),
    mesh_case("vtk not polydata", "a.vtk", legacy_vtk(b"", dataset=b"UNSTRUCTURED_GRID"), 'line 4: the dataset is UNSTRUCTURED_GRID, not a surface (POLYDATA): ' + EXTRACT_SURFACE),
    mesh_case("vtk truncated polygons", "a.vtk", legacy_vtk(b"POLYGONS 2 8\n3 0 1 2\n"), 'line 9: the file ends where value 5 of 8 of POLYGONS should be'),
    mesh_case("vtk garbage", "a.vtk", b"\x00\x01binary junk\xff", 'the file ends within its three header lines'),
    # found by fuzzing: NUL bytes in the version line crashed vtkDataReader
    mesh_case("vtk nul in version line", "a.vtk", b"# vtk DataFile Version\0\0\0 5.1\nt\nASCII\nDATASET POLYDATA\n",
              "line 1: a header line longer than 255 bytes or holding a NUL byte"),
    mesh_case("vtk no version", "a.vtk", b"# vtk DataFile\nt\nASCII\nDATASET POLYDATA\n",
              'line 1: expected "# vtk DataFile Version N.N", found "# vtk DataFile"'),
    # found by fuzzing: a version VTK cannot parse made it read 5.1 cell lists as 3.0 ones
    mesh_case("vtk unparsable version", "a.vtk",
              b"# vtk DataFile Version 5+.1\nt\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n"
              b"POLYGONS 2 3\nOFFSETS vtktypeint64\n0 3\nCONNECTIVITY vtktypeint64\n0 1 2\n",
              'line 1: expected "# vtk DataFile Version N.N", found "# vtk DataFile Version 5+.1"'),
    mesh_case("vtk offsets in a version 4 file", "a.vtk",
              b"# vtk DataFile Version 4.2\nt\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n"
              b"POLYGONS 2 3\nOFFSETS vtktypeint64\n0 3\nCONNECTIVITY vtktypeint64\n0 1 2\n",
              'line 8: POLYGONS: "OFFSETS" is not a number'),
    # found by fuzzing: VTK hung reading past a METADATA block of a binary file; its keys must be complete
    mesh_case("vtk metadata short of its keys", "a.vtk",
              b"# vtk DataFile Version 5.1\nt\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n"
              b"METADATA\nINFORMATION 2\nNAME L2_NORM_RANGE LOCATION vtkDataArray\nDATA 2 0.5 0.5\n\n",
              "line 11: METADATA announces 2 information keys and holds 1"),
    # OFF
    mesh_case("off index beyond", "a.off", TETRA_OFF.replace(b"3 1 2 3", b"3 1 2 4"), 'line 10: vertex index 4 is out of range [0, 4)'),
    mesh_case("off huge vertex count", "a.off", b"OFF\n1000000000000 1 0\n0 0 0\n", 'line 3: file ends after 1 of 1000000000000 vertices'),
    mesh_case("off huge face size", "a.off", b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3000000000 0 1 2\n", 'line 6: face has fewer than 3000000000 vertex indices'),
    mesh_case("off escape bytes as keyword", "a.off", b"\x1b[2J\x1b[31mOFF\n", 'line 1: expected "OFF", found "\\x1B[2J\\x1B[31mOFF"'),
    mesh_case("off nan", "a.off", TETRA_OFF.replace(b"1 0 0\n", b"nan 0 0\n"), 'point 1 has a NaN or infinite coordinate'),
    mesh_case("off truncated", "a.off", TETRA_OFF[:-8], 'line 9: file ends after 3 of 4 faces'),
    # glTF and GLB
    mesh_case("gltf missing buffer file", "a.gltf", gltf(uri="missing.bin"), 'buffers[0].uri: no file "missing.bin"'),
    mesh_case("gltf missing image file", "a.gltf",
              gltf(edit=lambda d: d.update(images=[{"uri": "missing.png"}], textures=[{"source": 0}])),
              'images[0].uri: no file "missing.png"'),
    # VTK reads a glTF's images whole: a FIFO hung it.
    mesh_case("gltf image is a device", "a.gltf",
              gltf(edit=lambda d: d.update(images=[{"uri": "/dev/zero"}], textures=[{"source": 0}])),
              'images[0].uri: not a regular file "/dev/zero"'),
    mesh_case("gltf buffer is a device", "a.gltf", gltf(uri="/dev/zero"), 'buffers[0].uri: not a regular file "/dev/zero"'),
    mesh_case("gltf accessor beyond buffer", "a.gltf", gltf(count=300), 'accessors[0]: 300 elements of 12 bytes from byte 0 reach beyond its bufferView of 36 bytes'),
    mesh_case("gltf index beyond positions", "a.gltf", gltf(index_values=(0, 1, 7)), 'polygon 0 names point 7, but the mesh has 3 points (0 to 2)'),
    mesh_case("gltf bufferView beyond buffer", "a.gltf",
              gltf(edit=lambda d: d["bufferViews"][1].update(byteLength=60)), 'bufferViews[1] (bytes 36 + 60) reaches beyond its buffer of 44 bytes'),
    mesh_case("gltf node cycle", "a.gltf",
              gltf(edit=lambda d: d.update(nodes=[{"mesh": 0, "children": [1]}, {"children": [0]}])), 'nodes[1].children: node 0 is its own ancestor'),
    mesh_case("gltf mesh reference beyond", "a.gltf", gltf(edit=lambda d: d["nodes"][0].update(mesh=4)), 'nodes[0].mesh = 4 names no mesh (there are 1)'),
    mesh_case("gltf attribute accessor beyond", "a.gltf",
              gltf(edit=lambda d: d["meshes"][0]["primitives"][0]["attributes"].update(POSITION=9)), 'meshes[0].primitives[0].attributes.POSITION = 9 names no accessor (there are 2)'),
    mesh_case("gltf short data uri", "a.gltf", gltf(edit=lambda d: d["buffers"][0].update(byteLength=400)), 'buffers[0] holds 44 bytes, its byteLength is 400'),
    mesh_case("gltf malformed json", "a.gltf", b"{\"asset\": {\"version\": \"2.0\"", "malformed glTF JSON: parse error at line 1, column 28: syntax error while parsing object - unexpected end of input; expected '}'"),
    mesh_case("gltf unknown component type", "a.gltf",
              gltf(edit=lambda d: d["accessors"][0].update(componentType=5130)), 'accessors[0] has an unknown componentType or type'),
    # found by fuzzing: vtkGLTFReader followed an accessor without a view, or of the wrong type
    mesh_case("gltf accessor without bufferView", "a.gltf", gltf(edit=lambda d: d["accessors"][1].pop("bufferView")),
              "accessors[1] has no bufferView (zero-filled accessors are not read)"),
    mesh_case("gltf bufferView without byteLength", "a.gltf",
              gltf(edit=lambda d: d["bufferViews"][0].pop("byteLength")), "bufferViews[0] has no byteLength"),
    mesh_case("glb indices of VEC3 floats", "a.glb",
              glb(edit=lambda d: d["meshes"][0]["primitives"][0].update(indices=0)),
              "meshes[0].primitives[0].indices: accessor 0 is not of type SCALAR with a component type VTK reads there"),
    mesh_case("gltf position of scalars", "a.gltf",
              gltf(edit=lambda d: d["meshes"][0]["primitives"][0]["attributes"].update(POSITION=1)),
              "meshes[0].primitives[0].attributes.POSITION: accessor 1 is not of type VEC3 with a component type VTK "
              "reads there"),
    mesh_case("glb primitive without positions", "a.glb",
              glb(edit=lambda d: d["meshes"][0]["primitives"][0].pop("attributes")),
              "meshes[0].primitives[0] has no attributes.POSITION"),
    mesh_case("gltf accessor without count", "a.gltf", gltf(edit=lambda d: d["accessors"][0].pop("count")),
              "accessors[0] has no count (at least 1)"),
    mesh_case("glb truncated", "a.glb", glb(cut=10), 'truncated binary glTF: its header announces 568 bytes, the file has 558'),
    mesh_case("glb bad magic", "a.glb", b"gLTF" + bytes(30), 'not a binary glTF file (no "glTF" header)'),
    mesh_case("glb accessor beyond buffer", "a.glb", glb(count=300), 'accessors[0]: 300 elements of 12 bytes from byte 0 reach beyond its bufferView of 36 bytes'),
    mesh_case("glb version 1", "a.glb", b"glTF\x01\0\0\0" + bytes(20), 'binary glTF version 1 (only 2 is read)'),
    # any mesh
    mesh_case("mesh is a directory", "d.obj", None, 'is a directory, not a mesh file'),
    mesh_case("mesh is a directory without extension", "d", None, 'is a directory, not a mesh file'),
    mesh_case("mesh missing", "nothere.obj", "skip", 'cannot open file: No such file or directory'),
    mesh_case("mesh unsupported extension", "a.xyz", b"1 2 3\n", 'unsupported mesh format ".xyz" (supported: .obj .ply .stl .vtp .vtk .off .gltf .glb)'),
    mesh_case("mesh of an unstructured grid", "a.vtu", b'<VTKFile type="UnstructuredGrid"/>\n',
              'unsupported mesh format ".vtu" (supported: .obj .ply .stl .vtp .vtk .off .gltf .glb): '
              'a VTK dataset that is not a surface; ' + EXTRACT_SURFACE),
    # Non-finite attributes
    # Normals, texture coordinates and tangents must be finite in every format (the filters carried a
    # NaN into their output, which ShadeLab's own OBJ reader then rejected); text formats name the line.
    ("ply ascii infinite normal", ["tangents", "a.ply", "-o", "out.obj"],
     {"a.ply": ply_ascii_attributes(b"1 0 0 inf 0 0 nan 0\n")}, 1,
     'shadelab tangents: a.ply: line 16 (element "vertex" row 2 of 4): nx "inf" is not a finite number\n'),
    mesh_case("ply ascii texture coordinate beyond float", "a.ply", ply_ascii_attributes(b"1 0 0 1 0 0 1e39 0\n"),
              'line 16 (element "vertex" row 2 of 4): u "1e39" is beyond the range of float'),
    mesh_case("ply ascii nan face texture coordinate", "a.ply",
              ply_header(b"ascii", 3, 1, b"property list uchar int vertex_indices\nproperty list uchar float texcoord") +
              b"0 0 0\n1 0 0\n0 1 0\n3 0 1 2 6 0 0 nan 0 0 1\n",
              'line 14 (element "face" row 1 of 1): texcoord "nan" is not a finite number'),
    # ShadeLab's own binary PLY parser takes this one.
    mesh_case("ply binary nan normal", "a.ply",
              ply_header(b"binary_little_endian", 3, 1).replace(
                  b"property float z\n", b"property float z\nproperty float nx\nproperty float ny\nproperty float nz\n") +
              struct.pack("<18f", 0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 1, 0, float("nan"), 0, 1) +
              struct.pack("<B3i", 3, 0, 1, 2),
              'point normals array "Normals", tuple 2: nan is not a finite number'),
    # The filters take the point array "Tangents" by name, active or not.
    ("vtp nan tangent", ["cosine", "a.vtp", "-o", "out.vtp"],
     {"a.vtp": vtp(b"0 1 2").replace(b"<Points>", b'<PointData>\n<DataArray type="Float32" Name="Tangents" '
                                     b'NumberOfComponents="4" format="ascii">1 0 0 1 1 0 0 1 nan 0 0 1</DataArray>\n'
                                     b'</PointData>\n<Points>')}, 1,
     'shadelab cosine: a.vtp: point tangents array "Tangents", tuple 2: nan is not a finite number\n'),
    # Other arrays keep their NaN ("missing value"): the scalars before the normals are passed over.
    mesh_case("vtk binary nan normal after nan scalars", "a.vtk",
              legacy_vtk_binary(b"SCALARS temperature float 1\nLOOKUP_TABLE default\n" +
                                struct.pack(">3f", 1, float("nan"), 2) + b"\nNORMALS n float\n" +
                                struct.pack(">9f", 0, 0, 1, 0, 0, 1, 0, float("-inf"), 1) + b"\n"),
              'point normals array "n", tuple 2: -inf is not a finite number'),
    mesh_case("vtk binary nan cell normal", "a.vtk",
              legacy_vtk_binary(b"TEXTURE_COORDINATES uv 2 float\n" + struct.pack(">6f", 0, 0, 1, 0, 0, 1) +
                                b"\nCELL_DATA 1\nNORMALS cn float\n" + struct.pack(">3f", 0, float("nan"), 1) + b"\n"),
              'cell normals array "cn", tuple 0: nan is not a finite number'),
    # VTK reads ASCII values with >>, which reads no "nan" or "inf" (in any section) and fails beyond float range.
    mesh_case("vtk ascii nan point", "a.vtk",
              b"# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 nan 1 0\n"
              b"POLYGONS 1 4\n3 0 1 2\n", 'line 6: POINTS: "nan" is not a finite number'),
    mesh_case("vtk ascii normal beyond float", "a.vtk",
              legacy_vtk(b"POLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\nNORMALS n float\n0 0 1 0 0 1e39 0 0 1\n"),
              'line 11: NORMALS: "1e39" is beyond the range of float'),
    mesh_case("vtk ascii nan scalar", "a.vtk",
              legacy_vtk(b"POLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\nSCALARS s double 1\nLOOKUP_TABLE default\n0\nnan\n1\n"),
              'line 13: SCALARS: "nan" is not a finite number'),
    # The displacement moved points to NaN, and the error blamed the mesh.
    ("detail displacement nan height", ["detail", "q.obj", "--displace", "h.exr", "-o", "out.vtp"],
     {"q.obj": QUAD_OBJ, "h.exr": half_exr(0x3800, 0x7E00)}, 1,
     'shadelab detail: q.obj: h.exr: pixel x 0, y 1 (from the top left), channel 0: nan is not a finite number\n'),
    # The bump and normal maps gave flat normals, with exit status 0.
    ("detail bump map nan height", ["detail", "q.obj", "--bump-map", "h.exr", "-o", "out.vtp"],
     {"q.obj": QUAD_OBJ, "h.exr": half_exr(0x3800, 0x7E00)}, 1,
     'shadelab detail: q.obj: h.exr: pixel x 0, y 1 (from the top left), channel 0: nan is not a finite number\n'),
    ("detail normal map nan texel", ["detail", "q.obj", "--normal-map", "h.exr", "-o", "out.vtp"],
     {"q.obj": QUAD_OBJ, "h.exr": half_exr(0x7C00, 0x3800)}, 1,
     'shadelab detail: q.obj: h.exr: pixel x 0, y 0 (from the top left), channel 0: inf is not a finite number\n'),
    # scenes
    scene_case("scene number beyond double", b'{"material": {"shininess": 1e400}}', 'material.shininess: the number 1e400 is beyond the range of a double'),
    scene_case("scene number beyond double in array", b'{"background": [0.1, 0.2, -1e999]}', 'background[2]: the number -1e999 is beyond the range of a double'),
    scene_case("scene malformed json", b'{"imageSize": [800, 600]', "line 1, column 25: malformed JSON: syntax error while parsing object - unexpected end of input; expected '}'"),
    scene_case("scene escape bytes", b'{"imageSize": \x1b[31m}', 'line 1, column 15: malformed JSON: syntax error while parsing value - invalid literal; last read: \'"imageSize": <U+001B>\''),
    scene_case("scene empty", b"", "line 1, column 1: malformed JSON: syntax error while parsing value - unexpected end of input; expected '[', '{', or a literal"),
    scene_case("scene nan literal", b'{"background": [NaN, 0, 0]}', 'line 1, column 17: malformed JSON: syntax error while parsing value - invalid literal; last read: \'"background": [N\''),
    scene_case("scene wrong type", b'{"imageSize": "big"}', 'imageSize: expected [width, height]'),
    scene_case("scene unknown key", b'{"colour": [1, 0, 0]}', 'colour: unknown key (allowed here: "$schema", "background", "brdf", "camera", "description", "imageSize", "lights", "material", "shading")'),
    scene_case("scene duplicate key", b'{"background": [0, 0, 0], "background": [1, 1, 1]}', 'background: duplicate key'),
    scene_case("scene shininess out of range", b'{"material": {"shininess": -1}}', 'material.shininess: -1 is out of range [0, 100000]'),
    scene_case("scene spot cutoff out of range", b'{"lights": [{"type": "spot", "cutoff": 95}]}', 'lights[0].cutoff: 95 is out of range (0, 90]'),
    scene_case("scene unknown light type", b'{"lights": [{"type": "laser"}]}', 'lights[0].type: "laser" is not one of ' + light_types()),
    scene_case("scene lights not an array", b'{"lights": {"type": "point"}}', 'lights: expected an array of lights, got an object'),
    scene_case("scene utf16", '{"imageSize": [64, 64]}'.encode("utf-16"), "line 1, column 1: malformed JSON: syntax error while parsing value - invalid literal; last read: '\\xFF'"),
    ("scene is a directory", ["cosine", "m.off", "--scene", "s.json", "-o", "out.vtp"], {"m.off": TETRA_OFF,
     "s.json": None}, 1, 'shadelab cosine: s.json: is a directory, not a scene file\n'),
    ("scene missing", ["cosine", "m.off", "--scene", "nothere.json", "-o", "out.vtp"], {"m.off": TETRA_OFF}, 1, 'shadelab cosine: nothere.json: cannot open scene file: No such file or directory\n'),
    # images
    image_case("png truncated", "t.png", png(cut=20), 'shadelab light: t.png: cannot read image: PNG chunk \'IDAT\' at byte 33 declares 16 bytes of data; 8 bytes remain in the file\n'),
    image_case("png bad crc", "t.png", png(crc_ok=False), 'shadelab light: t.png: cannot read image: PNG read error: IDAT: CRC error PNG library error\n'),
    image_case("png huge header", "t.png", png(width=100000, height=100000), 'shadelab light: t.png: cannot read image: its header declares 100000x100000 pixels of 3 channels, more than ShadeLab reads (2^28 values)\n'),
    # 8 + 25 bytes of signature and IHDR; the tEXt chunk's 9 bytes of data are 4 short of a CRC.
    image_case("png chunk longer than the file", "t.png", png(text_claim=1953300627), 'shadelab light: t.png: cannot read image: PNG chunk \'tEXt\' at byte 33 declares 1953300627 bytes of data; 5 bytes remain in the file\n'),
    image_case("exr attribute longer than the file", "t.exr", exr(1979711507), 'shadelab light: t.exr: cannot read image: EXR attribute \'comments\' (string) at byte 8 declares 1979711507 bytes; 3 bytes remain in the file\n'),
    image_case("exr attribute of negative size", "t.exr", exr(-5), 'shadelab light: t.exr: cannot read image: EXR attribute \'comments\' (string) at byte 8 declares -5 bytes; 3 bytes remain in the file\n'),
    image_case("exr name without its end", "t.exr", exr(), 'shadelab light: t.exr: cannot read image: EXR header at byte 8: an attribute name that does not end within 255 bytes or before the end of the file\n'),
    image_case("exr offset table longer than the file", "t.exr", exr_scanlines(lines=100000000, tail=b"\0" * 24), 'shadelab light: t.exr: cannot read image: EXR offset table at byte 277 has 100000000 chunks of 8 bytes; 24 bytes remain in the file\n'),
    image_case("exr value unlike its type", "t.exr", exr_scanlines(extra=exr_attribute(b"owner", b"int", b"\0" * 8)), 'shadelab light: t.exr: cannot read image: EXR attribute \'owner\' (int) at byte 276 declares 8 bytes, but its type takes 4 bytes\n'),
    image_case("exr channel list past its size", "t.exr", exr_scanlines(extra=exr_attribute(b"channels", b"chlist", b"R\0" + b"\0" * 16 + b"\0", size=10)), 'shadelab light: t.exr: cannot read image: EXR attribute \'channels\' (chlist) at byte 276 declares 10 bytes, but channel \'R\' does not fit in its size\n'),
    image_case("exr preview larger than its size", "t.exr", exr_scanlines(extra=exr_attribute(b"preview", b"preview", struct.pack("<II", 40000, 40000) + b"\0" * 8)), 'shadelab light: t.exr: cannot read image: EXR attribute \'preview\' (preview) at byte 276 declares 16 bytes, but its preview of 1600000000 pixels needs 6400000008 bytes\n'),
    image_case("exr huge tile", "t.exr", exr_scanlines(tiles=(32768, 32767), tail=struct.pack("<Q", 313) + b"\0" * 22), 'shadelab light: t.exr: cannot read image: EXR attribute \'tiles\' (tiledesc) at byte 276 declares tiles of 32768x32767 pixels of 1 channel, more than ShadeLab reads (2^28 values)\n'),
    image_case("tiff huge tile", "t.tif", tiff_tiled(32768), 'shadelab light: t.tif: cannot read image: its header declares tiles of 32768x32768 pixels of 1 channel, more than ShadeLab reads (2^28 values)\n'),
    image_case("exr string longer than its vector", "t.exr", exr_scanlines(extra=exr_attribute(b"notes", b"stringvector", struct.pack("<i", 1000000000) + b"abcd")), 'shadelab light: t.exr: cannot read image: EXR attribute \'notes\' (stringvector) at byte 276 declares 8 bytes, but the string at byte 299 does not fit in its size\n'),
    image_case("png garbage", "t.png", b"\x89PNG\r\n\x1a\n\x1b[31m garbage", 'shadelab light: t.png: cannot read image: PNG chunk \'m ga\' at byte 8 declares 458961713 bytes of data; 1 byte remains in the file\n'),
    image_case("png empty", "t.png", b"", 'shadelab light: t.png: cannot read image: Not a PNG file\n'),
    image_case("jpg truncated", "t.jpg", "seed:fuzz_image_jpg/gradient.jpg:300", 'shadelab light: t.jpg: cannot read image: JPEG error: Premature end of JPEG file ("t.jpg") Bad JPEG header for "t.jpg"\n'),
    image_case("jpg garbage", "t.jpg", b"\xff\xd8\xff\xe0 not really", 'shadelab light: t.jpg: cannot read image: JPEG error: Premature end of JPEG file ("t.jpg") Bad JPEG header for "t.jpg"\n'),
    image_case("hdr garbage", "t.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 99999 +X 99999\n", 'shadelab light: t.hdr: cannot read image: its header declares 99999x99999 pixels of 3 channels, more than ShadeLab reads (2^28 values)\n'),
    image_case("hdr without pixels", "t.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 0 +X 8\n", 'shadelab light: t.hdr: cannot read image: it has no pixels: its header declares 8x0 pixels of 3 channels\n'),
    image_case("image that is a volume", "t.jpg", dds_volume(), 'shadelab light: t.jpg: cannot read image: it holds a volume of 3 slices; ShadeLab reads 2D images only\n'),
    image_case("image missing", "nothere.png", "skip", 'shadelab light: nothere.png: cannot read image: Could not open file "nothere.png"\n'),
    image_case("image is a directory", "d.png", None, 'shadelab light: d.png: is a directory, not an image file\n'),
    # command lines
    cli_case("size overflow", ["render", "m.off", "--size", "4294967360x48", "-o", "out.png"], 'shadelab render: --size: "4294967360x48" is not WxH with 16 <= W, H <= 8192\n'),
    cli_case("size too small", ["render", "m.off", "--size", "8x8", "-o", "out.png"], 'shadelab render: --size: "8x8" is not WxH with 16 <= W, H <= 8192\n'),
    cli_case("size not numbers", ["render", "m.off", "--size", "wide", "-o", "out.png"], 'shadelab render: --size: "wide" is not WxH with 16 <= W, H <= 8192\n'),
    cli_case("size negative", ["render", "m.off", "--size", "-64x48", "-o", "out.png"], 'shadelab render: --size: "-64x48" is not WxH with 16 <= W, H <= 8192\n'),
    cli_case("render light beyond scene", ["render", "m.off", "--scene", "three.json", "--component", "cos",
                                           "--light", "5", "-o", "out.png"], 'shadelab render: --light: light 5 is out of range: three.json has 3 lights\n', status=1),
    cli_case("render light fraction", ["render", "m.off", "--component", "cos", "--light", "0.5", "-o", "out.png"],
             'shadelab render: --light: "0.5" is not a whole number\n'),
    cli_case("cosine light fraction", ["cosine", "m.off", "--light", "0.5", "-o", "out.vtp"], 'shadelab cosine: --light: "0.5" is not a whole number\n'),
    cli_case("cosine light beyond scene", ["cosine", "m.off", "--scene", "three.json", "--light", "5",
                                           "-o", "out.vtp"], 'shadelab cosine: --light: light 5 is out of range: three.json has 3 lights\n', status=1),
    cli_case("cosine light beyond the built-in scene", ["cosine", "m.off", "--light", "3", "-o", "out.vtp"],
             'shadelab cosine: --light: light 3 is out of range: the built-in scene has 3 lights\n', status=1),
    # -1 (every light) is what cosine does without --light; given, it is an index.
    cli_case("cosine light negative", ["cosine", "m.off", "--light", "-1", "-o", "out.vtp"],
             'shadelab cosine: --light: -1 is out of range [0, 1e+06]\n'),
    # N.L reads no lighting model: --model would change nothing.
    cli_case("cosine model", ["cosine", "m.off", "--model", "phong", "-o", "out.vtp"],
             'shadelab cosine: unknown option --model (see --help)\n'),
    # Options that would be accepted and change nothing.
    cli_case("light fields without image", ["light", "m.off", "--fields", "Diffuse", "-o", "out.vtp"],
             'shadelab light: --fields: only with --image FILE (it chooses the arrays the image shows)\n'),
    cli_case("cosine fields without image", ["cosine", "m.off", "--fields", "CosTheta_0", "-o", "out.vtp"],
             'shadelab cosine: --fields: only with --image FILE (it chooses the arrays the image shows)\n'),
    cli_case("reference fields without image", ["reference", "m.off", "--fields", "Radiance", "-o", "out.vtp"],
             'shadelab reference: --fields: only with --image FILE (it chooses the arrays the image shows)\n'),
    # The scene's material.diffuseTexture shades light's and reference's k_d as it does render's: a missing one is
    # an error.
    *((command + " scene texture missing", [command, "q.obj", "--scene", "t.json", "-o", "out.vtp"],
       {"q.obj": QUAD_OBJ, "t.json": b'{"material": {"diffuseTexture": "gone.png"}, "lights": [{"type": "directional"}]}'},
       1, 'shadelab ' + command + ': gone.png: cannot read image: Could not open file "gone.png" (material.diffuseTexture of '
       't.json)\n') for command in ("light", "reference")),
    # light and reference take --diffuse-array and --diffuse-texture the same way, with the same errors.
    *(cli_case(command + " diffuse array and texture", [command, "m.off", "--diffuse-array", "Normals",
                                                        "--diffuse-texture", "t.png", "-o", "out.vtp"],
               'shadelab ' + command + ': --diffuse-texture: give either --diffuse-array or --diffuse-texture, not both\n')
      for command in ("light", "reference")),
    *((command + " diffuse array missing", [command, "q.obj", "--diffuse-array", "Colour", "-o", "out.vtp"],
       {"q.obj": QUAD_OBJ}, 1, 'shadelab ' + command + ': q.obj: no point array "Colour" for the diffuse colour\n')
      for command in ("light", "reference")),
    ("reference diffuse texture missing", ["reference", "q.obj", "--diffuse-texture", "nothere.png", "-o", "out.vtp"],
     {"q.obj": QUAD_OBJ}, 1, 'shadelab reference: nothere.png: cannot read image: Could not open file "nothere.png"\n'),
    cli_case("reference envmap scale without envmap", ["reference", "m.off", "--envmap-scale", "2", "-o", "out.vtp"],
             'shadelab reference: --envmap-scale: only with --envmap FILE\n'),
    cli_case("reference light radius without lights", ["reference", "m.off", "--envmap", "sky.hdr", "--no-lights",
                                                       "--light-radius", "0.1", "-o", "out.vtp"],
             "shadelab reference: --light-radius: the scene's lights are left out (--no-lights)\n"),
    cli_case("reference sun angle without lights", ["reference", "m.off", "--envmap", "sky.hdr", "--no-lights",
                                                    "--sun-angle", "2", "-o", "out.vtp"],
             "shadelab reference: --sun-angle: the scene's lights are left out (--no-lights)\n"),
    cli_case("reference light radius zero", ["reference", "m.off", "--light-radius", "0", "-o", "out.vtp"],
             "shadelab reference: --light-radius: 0 is no sphere; give a radius above 0 (or leave it out for 1% of "
             "the mesh diagonal)\n"),
    cli_case("reference samples fraction", ["reference", "m.off", "--samples", "2.5", "-o", "out.vtp"],
             'shadelab reference: --samples: "2.5" is not a whole number\n'),
    cli_case("reference seed fraction", ["reference", "m.off", "--seed", "1.5", "-o", "out.vtp"],
             'shadelab reference: --seed: "1.5" is not a whole number\n'),
    ("tangents normals option on a mesh with normals", ["tangents", "n.obj", "--weighting", "area", "-o", "out.vtp"],
     {"n.obj": b"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nf 1/1/1 2/2/1 3/3/1\n"}, 1,
     "shadelab tangents: n.obj: --weighting: the mesh has point normals, which tangents keep; the normals options "
     "apply only to a mesh without them\n"),
    cli_case("detail strength of a bump map", ["detail", "m.off", "--bump-map", "h.png", "--strength", "2", "-o",
                                               "out.vtp"], 'shadelab detail: --strength: only with --normal-map\n'),
    cli_case("detail directx of a displacement", ["detail", "m.off", "--displace", "h.png", "--directx", "-o",
                                                  "out.vtp"], 'shadelab detail: --directx: only with --normal-map\n'),
    cli_case("detail scale of a normal map", ["detail", "m.off", "--normal-map", "n.png", "--scale", "0.1", "-o",
                                              "out.vtp"], 'shadelab detail: --scale: only with --bump-map or --displace\n'),
    cli_case("detail invert of a normal map", ["detail", "m.off", "--normal-map", "n.png", "--invert", "-o",
                                               "out.vtp"], 'shadelab detail: --invert: only with --bump-map or --displace\n'),
    cli_case("detail bump scale beyond the filter's", ["detail", "m.off", "--bump-map", "h.png", "--scale", "101",
                                                      "-o", "out.vtp"], 'shadelab detail: --scale: 101 is out of range [-100, 100]\n'),
    cli_case("detail displacement scale beyond the filter's", ["detail", "m.off", "--displace", "h.png", "--scale",
                                                              "-2e6", "-o", "out.vtp"], 'shadelab detail: --scale: -2e+06 is out of range [-1e+06, 1e+06]\n'),
    cli_case("detail strength beyond the filter's", ["detail", "m.off", "--normal-map", "n.png", "--strength", "10.5",
                                                    "-o", "out.vtp"], 'shadelab detail: --strength: 10.5 is out of range [0, 10]\n'),
    cli_case("lobe light beyond scene", ["lobe", "m.off", "--scene", "three.json", "--light", "5",
                                         "-o", "out.vtp"], 'shadelab lobe: --light: light 5 is out of range: three.json has 3 lights\n', status=1),
    cli_case("lobe light minus one", ["lobe", "m.off", "--scene", "three.json", "--light", "-1",
                                      "-o", "out.vtp"], 'shadelab lobe: --light: -1 is out of range [0, 1e+06]\n'),
    cli_case("render unknown component", ["render", "m.off", "--component", "glow", "-o", "out.png"], 'shadelab render: --component: "glow" is not one of total, ambient, diffuse, specular, emission, cos\n'),
    cli_case("unknown option", ["normals", "m.off", "--shiny", "-o", "out.vtp"], 'shadelab normals: unknown option --shiny (see --help)\n'),
    cli_case("missing output", ["normals", "m.off"], 'shadelab normals: missing -o/--output FILE\n'),
    cli_case("two meshes", ["tangents", "m.off", "m.off", "-o", "out.vtp"], 'shadelab tangents: expected one MESH argument, got 2\n'),
    cli_case("two meshes to one file", ["normals", "m.off", "m.off", "-o", "out.vtp"], 'shadelab normals: -o/--output: with 2 MESH arguments, "out.vtp" must be an existing folder\n'),
    cli_case("unknown compression", ["normals", "m.off", "-o", "out.vtp", "--compress", "gzip"], 'shadelab normals: --compress: unknown value "gzip" (none, lz4, zlib)\n'),
    cli_case("option without value", ["normals", "m.off", "-o"], 'shadelab normals: option -o needs a value (OUT)\n'),
    cli_case("unknown model", ["light", "m.off", "--model", "toon", "-o", "out.vtp"], 'shadelab light: --model: "toon" is not a lighting model (' + lighting_models() + ')\n'),
    cli_case("render anisotropic model without tangents", ["render", "m.off", "--model", "ward", "-o", "out.png"],
             'shadelab render: m.off: the ward model is anisotropic and needs tangents (a 4-component point array '
             '"Tangents"); compute them first (shadelab tangents, slPolyDataTangents)\n', status=1),
    cli_case("light anisotropic model without tangents", ["light", "m.off", "--model", "ashikhmin-shirley", "-o",
                                                         "out.vtp"],
             'shadelab light: m.off: the ashikhmin-shirley model is anisotropic and needs tangents (a 4-component '
             'point array "Tangents"); compute them first (shadelab tangents, slPolyDataTangents)\n', status=1),
    cli_case("compare anisotropic model without tangents", ["compare", "m.off", "--scene", "ward.json", "-o",
                                                           "out.png"],
             'shadelab compare: m.off: the ward model is anisotropic and needs tangents (a 4-component point array '
             '"Tangents"); compute them first (shadelab tangents, slPolyDataTangents)\n', status=1,
             files={"ward.json": b'{"shading": {"model": "ward"}, "lights": [{"type": "directional"}]}'}),
    cli_case("roughness out of range", ["render", "m.off", "--roughness", "1.5", "-o", "out.png"],
             'shadelab render: --roughness: 1.5 is out of range [0, 1]\n'),
    cli_case("ior below one", ["light", "m.off", "--ior", "0.5", "-o", "out.vtp"],
             'shadelab light: --ior: 0.5 is out of range [1, 10]\n'),
    cli_case("render brdf that does not parse", ["render", "m.off", "--brdf", "b.brdf", "-o", "out.png"],
             'shadelab render: b.brdf:2: float needs 4 values (float NAME MIN MAX DEFAULT), the line has 3\n', status=1,
             files={"b.brdf": b"::begin parameters\nfloat k 0 1\n::end parameters\n::begin shader\n::end shader\n"}),
    cli_case("render brdf glsl error", ["render", "m.off", "--brdf", "b.brdf", "-o", "out.png"],
             "shadelab render: b.brdf:3: `nothing' undeclared\n", status=1,
             files={"b.brdf": b"::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {\n  return nothing;\n}\n::end shader\n"}),
    cli_case("render brdf parameter out of range", ["render", "m.off", "--brdf", "b.brdf", "--param", "k=2", "-o", "out.png"],
             'shadelab render: b.brdf: --param "k=2": k 2 is out of range [0, 1] (line 2)\n', status=1,
             files={"b.brdf": b"::begin parameters\nfloat k 0 1 0.5\n::end parameters\n::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec3(k); }\n::end shader\n"}),
    cli_case("render param without brdf", ["render", "m.off", "--param", "k=2", "-o", "out.png"],
             'shadelab render: --param: needs --brdf FILE (or a scene with a "brdf")\n'),
    cli_case("unknown frequency", ["render", "m.off", "--frequency", "sometimes", "-o", "out.png"], 'shadelab render: --frequency: "sometimes" is not one of flat, gouraud, phong\n'),
    cli_case("unknown subcommand", ["paint", "m.off"], 'shadelab: unknown subcommand "paint" (see shadelab --help)\n'),
    # BRDF Explorer .brdf files (shadelab lobe --brdf)
    brdf_case("brdf unknown parameter type", b"::begin parameters\nint n 0 1 0\n::end parameters\n" + BRDF_SHADER,
              'b.brdf:2: unknown parameter type "int" (float, bool or color)'),
    brdf_case("brdf default out of range", b"::begin parameters\nfloat n 1 100 500\n::end parameters\n" + BRDF_SHADER,
              'b.brdf:2: n: the default 500 is out of range [1, 100]'),
    brdf_case("brdf shader without end", b"analytic\n::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)\n",
              'b.brdf:2: ::begin shader has no ::end shader (the file ends on line 3)'),
    brdf_case("brdf no shader", b"analytic\n# nothing else\n", 'b.brdf: no shader block (::begin shader ... ::end shader)'),
    brdf_case("brdf binary garbage", bytes(range(256)), 'b.brdf:1: control byte \\x00 in the text'),
    brdf_case("brdf glsl does not compile",
              b"analytic\n::begin parameters\nfloat roughness 0 1 0.5\n::end parameters\n::begin shader\n"
              b"vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)\n{\n    return vec3(roughnes);\n}\n::end shader\n",
              "b.brdf:8: `roughnes' undeclared"),
    brdf_case("brdf glsl does not link", b"::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y);\n::end shader\n",
              "b.brdf: unresolved reference to function `BRDF'"),
    brdf_case("brdf param out of range", b"::begin parameters\nfloat n 1 100 50\n::end parameters\n" + BRDF_SHADER,
              'b.brdf: --param "n=500": n 500 is out of range [1, 100] (line 2)', ["--param", "n=500"]),
    brdf_case("brdf unknown param", b"::begin parameters\nfloat n 1 100 50\n::end parameters\n" + BRDF_SHADER,
              'b.brdf: --param "k=1": the file has no parameter "k" (it has n)', ["--param", "k=1"]),
    brdf_case("brdf missing file", None, 'b.brdf: cannot open BRDF file: No such file or directory'),
    cli_case("brdf param before file", ["lobe", "--param", "n=3", "--brdf", "b.brdf", "-o", "out.png"],
             'shadelab lobe: --param n=3 comes before any --brdf FILE\n', files={"b.brdf": BRDF_SHADER}),
    cli_case("brdf lobes on a mesh", ["lobe", "m.off", "--brdf", "b.brdf", "-o", "out.png"],
             "shadelab lobe: --brdf: lobes on a mesh take the scene's model; a .brdf file's lobe is drawn alone\n",
             files={"b.brdf": BRDF_SHADER}),
    # Special files and lobe outputs
    # Every input must be a regular file: /dev/zero grew a scene's buffer without bound and a FIFO
    # hung the image reader (tests/apps/test_cli.py, under limits); /dev/null shows the check.
    ("scene is a device", ["cosine", "m.off", "--scene", "/dev/null", "-o", "out.vtp"], {"m.off": TETRA_OFF}, 1,
     "shadelab cosine: /dev/null: is not a regular file (a device, pipe or socket)\n"),
    *((command + " texture is a device", [command, "q.obj", "--diffuse-texture", "/dev/null", "-o", "out.vtp"],
       {"q.obj": QUAD_OBJ}, 1, "shadelab " + command + ": /dev/null: is not a regular file (a device, pipe or socket)\n")
      for command in ("light", "reference")),
    ("envmap is a device", ["reference", "m.off", "--envmap", "/dev/null", "--samples", "1", "-o", "out.vtp"],
     {"m.off": TETRA_OFF}, 1, "shadelab reference: /dev/null: is not a regular file (a device, pipe or socket)\n"),
    ("brdf is a device", ["lobe", "--brdf", "/dev/null", "-o", "out.png"], {}, 1,
     "shadelab lobe: /dev/null: is not a regular file (a device, pipe or socket)\n"),
    ("brdf is a directory", ["lobe", "--brdf", "b.brdf", "-o", "out.png"], {"b.brdf": None}, 1,
     "shadelab lobe: b.brdf: is a directory, not a BRDF file\n"),
    # lobe writes its outputs only when both can be made, and never one over the other.
    cli_case("lobe slice in a missing folder", ["lobe", "--model", "phong", "-o", "out.vtp", "--slice", "nodir/s.vtp"],
             "shadelab lobe: nodir/s.vtp: cannot create output file: No such file or directory\n", status=1),
    cli_case("lobe in a missing folder keeps the slice", ["lobe", "--model", "phong", "-o", "nodir/l.vtp", "--slice",
             "out.vtp"], "shadelab lobe: nodir/l.vtp: cannot create output file: No such file or directory\n", status=1),
    cli_case("lobe slice is the output", ["lobe", "--model", "phong", "-o", "out.vtp", "--slice", "./out.vtp"],
             "shadelab lobe: -o/--output and --slice would both write ./out.vtp\n"),
    # The image is written first: a mesh output that cannot be made stops the command before it.
    cli_case("cosine mesh in a missing folder keeps the image", ["cosine", "m.off", "-o", "nodir/m.vtp", "--image",
             "out.png"], "shadelab cosine: nodir/m.vtp: cannot create output file: No such file or directory\n", status=1),
    cli_case("reference mesh in a missing folder keeps the image", ["reference", "m.off", "-n", "1", "-o", "nodir/m.vtp",
             "--image", "out.png"], "shadelab reference: nodir/m.vtp: cannot create output file: No such file or directory\n",
             status=1),
    # --image and --fields belong to cosine, light and reference; lobe draws its own images.
    cli_case("lobe image option", ["lobe", "m.off", "-o", "out.vtp", "--image", "out.png"],
             "shadelab lobe: unknown option --image (see --help)\n"),
    cli_case("lobe fields option", ["lobe", "m.off", "-o", "out.vtp", "--fields", "BRDF"],
             "shadelab lobe: unknown option --fields (see --help)\n"),
    # Each of lobe's outputs takes options of its own; one another output would ignore is refused.
    cli_case("lobe slice of an image", ["lobe", "-o", "out.png", "--slice", "s.vtp"],
             "shadelab lobe: --slice: only for a single lobe as a mesh (-o LOBE.vtp)\n"),
    cli_case("lobe slice on a mesh", ["lobe", "m.off", "-o", "out.vtp", "--slice", "s.vtp"],
             "shadelab lobe: --slice: only for a single lobe as a mesh (-o LOBE.vtp)\n"),
    cli_case("lobe incidence on a mesh", ["lobe", "m.off", "-o", "out.vtp", "--incidence", "30"],
             "shadelab lobe: --incidence: only for a single lobe (-o LOBE.vtp or LOBE.png)\n"),
    cli_case("lobe ks in the albedo table", ["lobe", "--albedo-table", "-o", "t.csv", "--ks", "2"],
             "shadelab lobe: --ks: only for a single lobe (-o LOBE.vtp or LOBE.png)\n"),
    cli_case("lobe cosine in the albedo table", ["lobe", "--albedo-table", "-o", "t.csv", "--cosine"],
             "shadelab lobe: --cosine: only for lobes, not with --albedo-table\n"),
    cli_case("lobe models of a mesh", ["lobe", "-o", "out.vtp", "--models", "phong,ward"],
             "shadelab lobe: --models: only for a single lobe as an image (-o LOBE.png) or --albedo-table\n"),
    cli_case("lobe angles of an image", ["lobe", "-o", "out.png", "--angles", "30"],
             "shadelab lobe: --angles: only for --albedo-table\n"),
    cli_case("lobe one albedo angle", ["lobe", "--albedo-table", "-o", "t.csv", "--angles", "1"],
             "shadelab lobe: --angles: 1 is out of range [2, 1000]\n"),
    cli_case("lobe points of a single lobe", ["lobe", "-o", "out.vtp", "--points", "4"],
             "shadelab lobe: --points: only for lobes on MESH\n"),
    cli_case("lobe scene of a single lobe", ["lobe", "-o", "out.png", "--scene", "three.json"],
             "shadelab lobe: --scene: only for lobes on MESH (a single lobe takes --model and the material options)\n"),
    # render and compare refuse options their image would ignore, composites beyond the largest
    # image that can be rendered, and scenes with more lights than the lighting pass holds.
    cli_case("render component with vtk lighting", ["render", "m.off", "--vtk-lighting", "--component", "specular",
             "--false-color", "-o", "out.png"], "shadelab render: --component: only for ShadeLab's pass, not with --vtk-lighting\n"),
    cli_case("render light without component", ["render", "m.off", "--light", "1", "-o", "out.png"],
             "shadelab render: --light: only with --component ambient, diffuse, specular or cos\n"),
    cli_case("render light of emission", ["render", "m.off", "--component", "emission", "--light", "0", "-o", "out.png"],
             "shadelab render: --light: only with --component ambient, diffuse, specular or cos\n"),
    cli_case("render false colour without component", ["render", "m.off", "--false-color", "-o", "out.png"],
             "shadelab render: --false-color: only with --component ambient, diffuse, specular, emission or cos\n"),
    cli_case("render light beyond the pass", ["render", "m.off", "--component", "cos", "--light", "16", "-o", "out.png"],
             "shadelab render: --light: 16 is out of range [0, 15]\n"),
    cli_case("render more lights than the pass holds", ["render", "m.off", "--scene", "many.json", "-o", "out.png"],
             "shadelab render: many.json: 17 lights; ShadeLab's lighting pass draws at most 16\n", status=1,
             files={"many.json": json.dumps({"lights": [{"type": "directional"}] * 17}).encode()}),
    cli_case("compare more lights than the pass holds", ["compare", "m.off", "--scene", "many.json", "-o", "out.png"],
             "shadelab compare: many.json: 17 lights; ShadeLab's lighting pass draws at most 16\n", status=1,
             files={"many.json": json.dumps({"lights": [{"type": "directional"}] * 17}).encode()}),
    cli_case("compare amplify without diff", ["compare", "m.off", "--amplify", "2", "-o", "out.png"],
             "shadelab compare: --amplify: only with --diff\n"),
    cli_case("compare diff of one panel", ["compare", "m.off", "--grid", "phong", "--diff", "-o", "out.png"],
             "shadelab compare: --diff: needs two panels to compare (--grid names 1)\n"),
    cli_case("compare beyond the largest image", ["compare", "m.off", "--size", "6000x200", "-o", "out.png"],
             "shadelab compare: --size: 3 panels of 6000x200, 3 a row, make a 18000x200 image; "
             "at most 16384x16384 can be rendered\n"),
]

# A UTF-8 byte order mark: ShadeLab's OBJ parser skips it; a file that goes to vtkOBJReader (here for its
# negative indices) is refused unless the mark's line is blank or a comment, as VTK would skip the line. The
# other text formats name the mark with their first keyword.
CASES += [
    mesh_case("obj byte order mark before a vtkOBJReader file", "a.obj",
              b"\xef\xbb\xbfv 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf -4 -3 -2\n",
              'line 1: "v" follows a UTF-8 byte order mark, which VTK\'s OBJ reader would read as part of it and skip '
              'the line; save the file without the mark'),
    mesh_case("off byte order mark", "a.off", b"\xef\xbb\xbf" + TETRA_OFF, 'line 1: expected "OFF", found "\\xEF\\xBB\\xBFOFF"'),
    mesh_case("ply byte order mark", "a.ply", b"\xef\xbb\xbf" + ply_ascii(b"3 0 1 2\n"),
              'line 1: expected "ply", found "\\xEF\\xBB\\xBFply"'),
    mesh_case("stl byte order mark", "a.stl",
              b"\xef\xbb\xbfsolid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
              b"endfacet\nendsolid a\n",
              "STLReader: error while reading file a.stl at line 1: Parse error. Expecting 'solid' found "
              "'\\xEF\\xBB\\xBFsolid'"),
]

# Legacy VTK as vtkDataWriter writes it: vtkIdType as 32-bit int; strings one a line in ASCII, and in binary
# each after a big-endian length of 1, 2, 4 or 8 bytes (the first byte's top two bits: 3, 2, 1, 0), which
# VTK allocates before it reads.
CASES += [
    mesh_case("vtk binary vtkIdType values are 32-bit", "a.vtk",
              legacy_vtk_binary(b"FIELD FieldData 1\nids 1 3 vtkIdType\n" + struct.pack(">2i", 5, -1)),
              'FIELD array "ids": 3 values need 12 bytes, the file has 8 after its keyword line'),
    mesh_case("vtk binary string longer than the file", "a.vtk",
              legacy_vtk_binary(b"FIELD FieldData 1\nnames 1 3 string\n\xc2ab\x80\x05abcde\x7f\xff\xff\xf0"),
              'FIELD array "names": string 3 of 3 is 1073741808 bytes long, the file has 0 after its length'),
    mesh_case("vtk binary strings cut", "a.vtk", legacy_vtk_binary(b"FIELD FieldData 1\nnames 1 3 string\n\xc2ab"),
              'line 12: FIELD array "names": the file ends after 1 of 3 strings'),
    mesh_case("vtk ascii strings cut", "a.vtk",
              legacy_vtk(b"POLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\nFIELD FieldData 1\nnames 1 3 string\nab\ncd\n"),
              'line 14: FIELD array "names": the file ends after 2 of 3 strings'),
    mesh_case("vtk ascii string with a short escape", "a.vtk",
              legacy_vtk(b"POLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\nFIELD FieldData 1\nnames 1 3 string\nab\n%\ncd\n"),
              'line 13: FIELD array "names": string "%" holds a % in fewer than 3 characters, which VTK decodes by '
              'reading past its end'),
]

# OFF, COFF (r g b [a] after each vertex: integers 0-255, or 0-1 when any is written otherwise) and NOFF.
CASES += [
    mesh_case("off colour after a plain vertex", "a.off", TETRA_OFF.replace(b"1 0 0\n", b"1 0 0 255 0 0\n"),
              'line 4: 6 values for a vertex of plain OFF, which has 3 (x y z); a COFF header reads colours after them, '
              'NOFF normals'),
    mesh_case("coff colour beyond 255", "a.off", b"COFF\n3 1 0\n0 0 0 255 0 0\n1 0 0 300 0 0\n0 1 0 0 0 0\n3 0 1 2\n",
              'line 4: colour value "300" is not a number from 0 to 255 (integers) or 0 to 1'),
    mesh_case("coff float colour above 1", "a.off", b"COFF\n3 1 0\n0 0 0 0.5 0 0\n1 0 0 2 0 0\n0 1 0 0 0 0\n3 0 1 2\n",
              'line 4: colour value above 1 in a file of float colours (0 to 1)'),
    mesh_case("coff vertex without its colour", "a.off", b"COFF\n3 1 0\n0 0 0 1 0 0\n1 0 0\n0 1 0 0 0 0\n3 0 1 2\n",
              'line 4: expected a COFF vertex: x y z r g b [a]'),
    mesh_case("noff vertex without its normal", "a.off", b"NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0\n0 1 0 0 0 1\n3 0 1 2\n",
              'line 4: expected a NOFF vertex: x y z nx ny nz'),
    mesh_case("off variant not read", "a.off", b"STOFF\n3 1 0\n", 'line 1: "STOFF" files are not read (ShadeLab reads OFF, COFF and NOFF)'),
]
