"""Byte builders for the bad-input cases: small valid files of every format,
from which each case breaks one thing."""
import base64
import json
import os
import re
import struct
import zlib

TETRA_OFF = b"OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"

# A quad with texture coordinates: input of the image cases.
QUAD_OBJ = b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n"

THREE_LIGHTS = json.dumps({"lights": [
    {"type": "directional", "direction": [0, 0, -1]},
    {"type": "point", "position": [0, 2, 2]},
    {"type": "ambient", "ambient": [0.2, 0.2, 0.2]},
]}).encode()


TABLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "filters", "core", "lighting", "include",
                      "shadelab", "LightingTables.h")


def table_names(macro):
    """The scene-file names of the rows of X-macro @p macro in LightingTables.h, in row order."""
    with open(TABLES) as f:
        text = f.read()
    body = text[text.index("#define " + macro + "(X)"):]
    body = body[:body.index("\n\n")]
    return re.findall(r'X\(\w+, \w+, "([^"]+)"', body)


def lighting_models():
    """The lighting models as messages list them: "lambert, phong, ..."."""
    return ", ".join(table_names("SHADELAB_LIGHTING_MODELS"))


def light_types():
    """The light types as the scene reader lists them: '"directional", "point", ...'."""
    return ", ".join('"' + name + '"' for name in table_names("SHADELAB_LIGHT_TYPES"))


def obj(faces, extra=b""):
    return b"v 0 0 0\nv 1 0 0\nv 0 1 0\n" + extra + faces


def ply_header(fmt, vertices, faces, face_property=b"property list uchar int vertex_indices"):
    return (b"ply\nformat " + fmt + b" 1.0\nelement vertex " + str(vertices).encode() +
            b"\nproperty float x\nproperty float y\nproperty float z\nelement face " + str(faces).encode() +
            b"\n" + face_property + b"\nend_header\n")


def ply_ascii(face_lines, vertices=3, faces=1):
    return ply_header(b"ascii", vertices, faces) + b"0 0 0\n1 0 0\n0 1 0\n" + face_lines


def ply_binary(indices, vertices=3, faces=1, cut=0):
    body = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    body += struct.pack("<B", len(indices)) + struct.pack("<%di" % len(indices), *indices)
    data = ply_header(b"binary_little_endian", vertices, faces) + body
    return data[:len(data) - cut]


def stl_binary(triangles, declared=None, cut=0):
    data = b"binary STL".ljust(80, b"\0") + struct.pack("<I", triangles if declared is None else declared)
    for t in range(triangles):
        data += struct.pack("<12fH", 0, 0, 1, t, 0, 0, t + 1, 0, 0, t, 1, 0, 0)
    return data[:len(data) - cut]


def vtp(connectivity, points=3, offsets=b"3"):
    return (b'<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">\n'
            b'<PolyData>\n<Piece NumberOfPoints="' + str(points).encode() +
            b'" NumberOfVerts="0" NumberOfLines="0" NumberOfStrips="0" NumberOfPolys="1">\n'
            b'<Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0'
            b'</DataArray></Points>\n<Polys>\n<DataArray type="Int64" Name="connectivity" format="ascii">' +
            connectivity + b'</DataArray>\n<DataArray type="Int64" Name="offsets" format="ascii">' + offsets +
            b'</DataArray>\n</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n')


def legacy_vtk(polygons, dataset=b"POLYDATA"):
    return (b"# vtk DataFile Version 3.0\nbad input\nASCII\nDATASET " + dataset +
            b"\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n" + polygons)


def gltf_parts(index_values=(0, 1, 2), count=3):
    positions = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    indices = struct.pack("<3H", *index_values) + b"\0\0"
    data = positions + indices
    document = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(data)}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
        ],
    }
    return document, data


def gltf(edit=None, uri=None, **parts):
    document, data = gltf_parts(**parts)
    document["buffers"][0]["uri"] = uri or ("data:application/octet-stream;base64," + base64.b64encode(data).decode())
    if edit:
        edit(document)
    return json.dumps(document).encode()


def glb(edit=None, cut=0, **parts):
    document, data = gltf_parts(**parts)
    if edit:
        edit(document)
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    body = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(data), b"BIN\0") + data
    out = struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body
    return out[:len(out) - cut]


def png(width=4, height=4, crc_ok=True, cut=0, text_claim=None):
    """A 4-row RGB PNG; with @text_claim, the IHDR is followed by a tEXt chunk
    whose length field claims @text_claim bytes and the file ends 9 bytes later."""
    def chunk(kind, payload, good=True):
        crc = zlib.crc32(kind + payload) ^ (0 if good else 1)
        return struct.pack(">I", len(payload)) + kind + payload + struct.pack(">I", crc)
    rows = b"".join(b"\0" + b"\x80\x40\x20" * width for _ in range(min(height, 4)))
    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    if text_claim is not None:
        return data + struct.pack(">I", text_claim) + b"tEXtComment\0x"
    data += chunk(b"IDAT", zlib.compress(rows), crc_ok) + chunk(b"IEND", b"")
    return data[:len(data) - cut]


def exr(attribute_size=None, name=b"comments"):
    """The start of an OpenEXR header: one string attribute @name whose size
    field says @attribute_size, followed by 3 bytes; or, with @attribute_size
    None, a 300-byte name with no NUL after it."""
    head = b"\x76\x2f\x31\x01\x02\x00\x00\x00"
    if attribute_size is None:
        return head + b"n" * 300
    return head + name + b"\0string\0" + struct.pack("<i", attribute_size) + b"abc"


def exr_attribute(name, kind, value, size=None):
    """One OpenEXR header attribute; @size overrides the size field."""
    return name + b"\0" + kind + b"\0" + struct.pack("<i", len(value) if size is None else size) + value


def exr_scanlines(lines=4, compression=0, extra=b"", tail=b"", tiles=None):
    """A single-part scan-line OpenEXR header: one half channel Y, a data
    window 1 pixel wide and @lines high, @compression, then @extra
    attributes; after its end, @tail (where the offset table belongs).
    With @tiles (width, height) the part is tiled (one level) instead."""
    channels = b"Y\0" + struct.pack("<iB3xii", 1, 0, 1, 1) + b"\0"
    if tiles is not None:
        extra = exr_attribute(b"tiles", b"tiledesc", struct.pack("<IIB", tiles[0], tiles[1], 0)) + extra
    header = (exr_attribute(b"channels", b"chlist", channels)
              + exr_attribute(b"compression", b"compression", bytes([compression]))
              + exr_attribute(b"dataWindow", b"box2i", struct.pack("<4i", 0, 0, 0, lines - 1))
              + exr_attribute(b"displayWindow", b"box2i", struct.pack("<4i", 0, 0, 0, lines - 1))
              + exr_attribute(b"lineOrder", b"lineOrder", b"\0")
              + exr_attribute(b"pixelAspectRatio", b"float", struct.pack("<f", 1.0))
              + exr_attribute(b"screenWindowCenter", b"v2f", struct.pack("<2f", 0.0, 0.0))
              + exr_attribute(b"screenWindowWidth", b"float", struct.pack("<f", 1.0)))
    flags = b"\x02\x00\x00\x00" if tiles is None else b"\x02\x02\x00\x00"
    return b"\x76\x2f\x31\x01" + flags + header + extra + b"\0" + tail


def tiff_tiled(tile, width=4, height=4):
    """A little-endian TIFF of @width x @height 8-bit grey pixels in tiles of
    @tile x @tile pixels, with the data of one 4 x 4 tile."""
    entries = [(256, 4, width), (257, 4, height), (258, 3, 8), (259, 3, 1), (262, 3, 1),
               (277, 3, 1), (284, 3, 1), (322, 4, tile), (323, 4, tile)]
    count = len(entries) + 2
    data_at = 8 + 2 + 12 * count + 4
    entries += [(324, 4, data_at), (325, 4, 16)]
    data = b"II*\0" + struct.pack("<IH", 8, count)
    for tag, kind, value in entries:
        field = struct.pack("<HH", value, 0) if kind == 3 else struct.pack("<I", value)  # SHORT or LONG
        data += struct.pack("<HHI", tag, kind, 1) + field
    return data + struct.pack("<I", 0) + b"\x80" * 16


def dds_volume(width=7, height=17, depth=3):
    """A DirectDraw Surface volume texture: @depth slices of @width x @height
    8-bit luminance pixels, a 3D image that OpenImageIO reads as one."""
    flags = 0x1 | 0x2 | 0x4 | 0x1000 | 0x800000  # caps, height, width, pixel format, depth
    header = struct.pack("<4sIIIIIII11I", b"DDS ", 124, flags, height, width, width, depth, 0, *([0] * 11))
    pixel_format = struct.pack("<IIIIIIII", 32, 0x20000, 0, 8, 0xFF, 0, 0, 0)  # luminance, 8 bits
    caps = struct.pack("<IIIII", 0x1000 | 0x8, 0x200000, 0, 0, 0)  # texture, complex; volume
    return header + pixel_format + caps + bytes(width * height * depth)


def vtp_compressed_header(blocks, last=0, sizes=()):
    """A zlib-compressed VTP whose points array's header declares @blocks
    blocks, the last one of @last bytes, and the compressed @sizes."""
    header = base64.b64encode(struct.pack("<%dI" % (3 + len(sizes)), blocks, 32768, last, *sizes))
    return (b'<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian" '
            b'header_type="UInt32" compressor="vtkZLibDataCompressor">\n<PolyData>\n'
            b'<Piece NumberOfPoints="3" NumberOfVerts="0" NumberOfLines="0" NumberOfStrips="0" NumberOfPolys="0">\n'
            b'<Points><DataArray type="Float32" Name="Points" NumberOfComponents="3" format="binary">' + header +
            b'</DataArray></Points>\n</Piece>\n</PolyData>\n</VTKFile>\n')


def vtp_appended_base64_header(blocks, header=None):
    """A compressed VTP with base64 appended data whose points header declares
    @blocks blocks, or is the base64 text @header."""
    header = header if header is not None else base64.b64encode(struct.pack("<III", blocks, 32768, 0))
    return (b'<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian" '
            b'header_type="UInt32" compressor="vtkZLibDataCompressor">\n<PolyData>\n'
            b'<Piece NumberOfPoints="3" NumberOfVerts="0" NumberOfLines="0" NumberOfStrips="0" NumberOfPolys="0">\n'
            b'<Points><DataArray type="Float32" Name="Points" NumberOfComponents="3" format="appended" offset="0"/>'
            b'</Points>\n</Piece>\n</PolyData>\n<AppendedData encoding="base64">\n_' + header +
            b'\n</AppendedData>\n</VTKFile>\n')
