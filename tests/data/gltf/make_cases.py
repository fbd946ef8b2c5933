#!/usr/bin/env python3
"""Writes the tiny hand-made glTF files used by tests/baker/import/gltf_import_test.cpp.

Each case is a .gltf with its buffer (and images) embedded as data URIs, so a file is
self-contained and readable. Run from this directory: python3 make_cases.py
The expected values asserted by the tests are derived by hand in the comments below.
"""
import base64
import json
import math
import struct
import zlib

FLOAT, UBYTE, USHORT, UINT = 5126, 5121, 5123, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963


def png_1x1(rgba):
    """A valid 1x1 RGBA8 PNG (so texture decoding of these cases would also work)."""
    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)
    ihdr = struct.pack(">IIBBBBB", 1, 1, 8, 6, 0, 0, 0)
    idat = zlib.compress(b"\x00" + bytes(rgba))
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", idat) + chunk(b"IEND", b"")


class Gltf:
    def __init__(self):
        self.bin = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": "lfd tests/data/gltf/make_cases.py"},
                    "buffers": [], "bufferViews": [], "accessors": []}

    def view(self, data, target=None, stride=None):
        while len(self.bin) % 4:
            self.bin.append(0)
        v = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if target:
            v["target"] = target
        if stride:
            v["byteStride"] = stride
        self.bin += data
        self.doc["bufferViews"].append(v)
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, fmt, values, type_, component, target=None, normalized=False, minmax=False):
        data = b"".join(struct.pack("<" + fmt, *(v if isinstance(v, (list, tuple)) else [v])) for v in values)
        a = {"bufferView": self.view(data, target), "componentType": component, "count": len(values), "type": type_}
        if normalized:
            a["normalized"] = True
        if minmax:
            rows = [v if isinstance(v, (list, tuple)) else [v] for v in values]
            a["min"] = [min(v[i] for v in rows) for i in range(len(rows[0]))]
            a["max"] = [max(v[i] for v in rows) for i in range(len(rows[0]))]
        self.doc["accessors"].append(a)
        return len(self.doc["accessors"]) - 1

    def positions(self, pts):
        return self.accessor("fff", pts, "VEC3", FLOAT, ARRAY_BUFFER, minmax=True)

    def vec3(self, v):
        return self.accessor("fff", v, "VEC3", FLOAT, ARRAY_BUFFER)

    def indices(self, idx, component=USHORT):
        fmt = {UBYTE: "B", USHORT: "H", UINT: "I"}[component]
        return self.accessor(fmt, idx, "SCALAR", component, ELEMENT_ARRAY_BUFFER)

    def times(self, v):
        """Animation key times: glTF requires their min and max."""
        return self.accessor("f", v, "SCALAR", FLOAT, minmax=True)

    def image(self, png):
        self.doc.setdefault("images", []).append(
            {"uri": "data:image/png;base64," + base64.b64encode(png).decode()})
        self.doc.setdefault("textures", []).append({"source": len(self.doc["images"]) - 1})
        return len(self.doc["textures"]) - 1

    def single_node_scene(self, mesh=0):
        self.doc["nodes"] = [{"mesh": mesh}]
        self.doc["scenes"] = [{"nodes": [0]}]
        self.doc["scene"] = 0

    def write(self, name):
        self.doc["buffers"] = [{"byteLength": len(self.bin),
                                "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(self.bin)).decode()}]
        with open(name, "w") as f:
            json.dump(self.doc, f, indent=1)
            f.write("\n")


UP = (0.0, 0.0, 1.0)
TRIANGLE = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]


def unit_triangle(g):
    """One ccw unit triangle in z = 0 with +z normals; returns the attributes."""
    return {"POSITION": g.positions(TRIANGLE), "NORMAL": g.vec3([UP] * 3)}


def strip():
    # Zig-zag strip, every triangle ccw (+z). Primitive 0, indices 0..5:
    #   (0,1,2) (1,3,2) (2,3,4) (3,5,4)          [odd triangles swap their last two]
    # Primitive 1, indices [0,1,2,2,3]: (0,1,2), then (1,2,2) and (2,2,3) are degenerate
    # stitching triangles and are dropped; vertex 3 is then unused and not stored.
    g = Gltf()
    pts = [(0, 1, 0), (0, 0, 0), (1, 1, 0), (1, 0, 0), (2, 1, 0), (2, 0, 0)]
    attrs = {"POSITION": g.positions([tuple(map(float, p)) for p in pts]), "NORMAL": g.vec3([UP] * 6)}
    g.doc["meshes"] = [{"name": "strip", "primitives": [
        {"attributes": attrs, "indices": g.indices([0, 1, 2, 3, 4, 5], UBYTE), "mode": 5},
        {"attributes": attrs, "indices": g.indices([0, 1, 2, 2, 3], UBYTE), "mode": 5}]}]
    g.single_node_scene()
    g.write("strip.gltf")


def fan():
    # Non-indexed fan around vertex 0: (1,2,0) (2,3,0) (3,4,0), all ccw (+z).
    g = Gltf()
    pts = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (-1, 1, 0)]
    attrs = {"POSITION": g.positions([tuple(map(float, p)) for p in pts]), "NORMAL": g.vec3([UP] * 5)}
    g.doc["meshes"] = [{"name": "fan", "primitives": [{"attributes": attrs, "mode": 6}]}]
    g.single_node_scene()
    g.write("fan.gltf")


def no_normals():
    # Non-indexed triangle list without NORMAL: flat normals are generated (+z for the
    # first, ccw triangle; -z for the second, cw one), vertices stay 0..5.
    g = Gltf()
    pts = TRIANGLE + [(0.0, 0.0, 1.0), (0.0, 1.0, 1.0), (1.0, 0.0, 1.0)]
    g.doc["meshes"] = [{"name": "flat", "primitives": [{"attributes": {"POSITION": g.positions(pts)}}]}]
    g.single_node_scene()
    g.write("no_normals.gltf")


def hierarchy():
    # nodes[0] (mesh) is a child of nodes[1] (matrix); nodes[2] is not in the scene.
    # nodes[1].matrix = T(1,2,3) * Rz(90 deg) * S(2,3,4), column-major.
    # Animation channel 0 targets nodes[0] (-> imported node 1), channel 1 targets the
    # dropped nodes[2] and is ignored.
    g = Gltf()
    attrs = unit_triangle(g)
    g.doc["meshes"] = [{"name": "tri", "primitives": [{"attributes": attrs}]}]
    c, s = math.cos(math.pi / 2), math.sin(math.pi / 2)
    m = [c * 2, s * 2, 0, 0, -s * 3, c * 3, 0, 0, 0, 0, 4, 0, 1, 2, 3, 1]
    g.doc["nodes"] = [{"name": "child", "mesh": 0, "translation": [0, 0, 5]},
                      {"name": "parent", "matrix": m, "children": [0]},
                      {"name": "orphan", "translation": [9, 9, 9]}]
    g.doc["scenes"] = [{"nodes": [1]}]
    g.doc["scene"] = 0
    t = g.times([0.0, 1.0])
    v = g.vec3([(0.0, 0.0, 5.0), (0.0, 0.0, 6.0)])
    g.doc["animations"] = [{"name": "move", "samplers": [{"input": t, "output": v, "interpolation": "STEP"}],
                            "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}},
                                         {"sampler": 0, "target": {"node": 2, "path": "translation"}}]}]
    g.write("hierarchy.gltf")


def sheared():
    g = Gltf()
    g.doc["meshes"] = [{"primitives": [{"attributes": unit_triangle(g)}]}]
    g.doc["nodes"] = [{"name": "skewed", "mesh": 0, "matrix": [1, 0, 0, 0, 0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}]
    g.doc["scenes"] = [{"nodes": [0]}]
    g.write("sheared_matrix.gltf")


def recursive():
    g = Gltf()
    g.doc["meshes"] = [{"primitives": [{"attributes": unit_triangle(g)}]}]
    g.doc["nodes"] = [{"name": "a", "mesh": 0, "children": [1]}, {"name": "b", "children": [0]}]
    g.doc["scenes"] = [{"nodes": [0]}]
    g.write("recursive_nodes.gltf")


def accessor_out_of_bounds():
    # POSITION claims 4 vertices but its bufferView holds 3.
    g = Gltf()
    attrs = unit_triangle(g)
    g.doc["accessors"][attrs["POSITION"]]["count"] = 4
    g.doc["meshes"] = [{"primitives": [{"attributes": attrs}]}]
    g.single_node_scene()
    g.write("accessor_out_of_bounds.gltf")


def index_out_of_range():
    g = Gltf()
    g.doc["meshes"] = [{"primitives": [{"attributes": unit_triangle(g), "indices": g.indices([0, 1, 3])}]}]
    g.single_node_scene()
    g.write("index_out_of_range.gltf")


# A 4x4 lossless WebP whose every pixel is (40, 200, 90, 128), straight alpha. Made with
# Pillow 9.4: Image.new("RGBA", (4, 4), (40, 200, 90, 128)).save(f, "WEBP", lossless=True).
WEBP_4X4 = base64.b64decode("UklGRh4AAABXRUJQVlA4TBEAAAAvA8AAEAdQ5KJUq4CBiOh/AAA=")
# The KTX2 file identifier and nothing decodable: the baker never decodes KTX2.
KTX2_STUB = b"\xabKTX 20\xbb\r\n\x1a\n" + bytes(68)


def data_image(g, data, media):
    g.doc.setdefault("images", []).append(
        {"uri": "data:%s;base64,%s" % (media, base64.b64encode(data).decode()), "mimeType": media})
    return len(g.doc["images"]) - 1


def textured_triangle(g, texture):
    """The unit triangle with uvs, its material's base colour from `texture`."""
    attrs = unit_triangle(g)
    attrs["TEXCOORD_0"] = g.accessor("ff", [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)], "VEC2", FLOAT, ARRAY_BUFFER)
    g.doc["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": texture}}}]
    g.doc["meshes"] = [{"primitives": [{"attributes": attrs, "material": 0}]}]
    g.single_node_scene()


def webp_fallback():
    # EXT_texture_webp used, not required: the texture's core source is a red PNG, its
    # WebP source the WEBP_4X4 colour. The baker takes the WebP (the image the author
    # intended), with its alpha straight: every texel (40, 200, 90, 128).
    g = Gltf()
    g.doc["extensionsUsed"] = ["EXT_texture_webp"]
    png, webp = data_image(g, png_1x1([255, 0, 0, 255]), "image/png"), data_image(g, WEBP_4X4, "image/webp")
    g.doc["textures"] = [{"source": png, "extensions": {"EXT_texture_webp": {"source": webp}}}]
    textured_triangle(g, 0)
    g.write("webp_fallback.gltf")


def basisu(required):
    # KHR_texture_basisu: its KTX2 image is never decoded. Used only: the core source (a
    # red 1x1 PNG) is baked, with a warning. Required (no core source): refused.
    g = Gltf()
    g.doc["extensionsUsed"] = ["KHR_texture_basisu"]
    ktx2 = data_image(g, KTX2_STUB, "image/ktx2")
    texture = {"extensions": {"KHR_texture_basisu": {"source": ktx2}}}
    if required:
        g.doc["extensionsRequired"] = ["KHR_texture_basisu"]
    else:
        texture["source"] = data_image(g, png_1x1([255, 0, 0, 255]), "image/png")
    g.doc["textures"] = [texture]
    textured_triangle(g, 0)
    g.write("basisu_required.gltf" if required else "basisu_fallback.gltf")


def quantized_normals(bad):
    # KHR_mesh_quantization: NORMAL as normalized BYTE (4-byte stride). Each unit normal is
    # rounded to the 1/127 grid: (1,1,1)/sqrt(3) -> (73,73,73), length 0.99557 - off by
    # more than float rounding, within one grid step: no warning. With `bad`, vertex 2's
    # normal is (64,0,0), length 0.504: a wrong vector, which still warns.
    g = Gltf()
    g.doc["extensionsUsed"] = g.doc["extensionsRequired"] = ["KHR_mesh_quantization"]
    normals = [(73, 73, 73, 0), (0, 0, 127, 0), (64, 0, 0, 0) if bad else (0, 90, 90, 0)]
    n = g.accessor("bbbb", normals, "VEC3", 5120, ARRAY_BUFFER, normalized=True)
    g.doc["bufferViews"][g.doc["accessors"][n]["bufferView"]]["byteStride"] = 4
    g.doc["meshes"] = [{"primitives": [{"attributes": {"POSITION": g.positions(TRIANGLE), "NORMAL": n}}]}]
    g.single_node_scene()
    g.write("quantized_bad_normal.gltf" if bad else "quantized_normals.gltf")


def missing_bin():
    g = Gltf()
    g.doc["meshes"] = [{"primitives": [{"attributes": unit_triangle(g)}]}]
    g.single_node_scene()
    g.write("missing_bin.gltf")
    doc = json.load(open("missing_bin.gltf"))
    doc["buffers"][0]["uri"] = "missing_bin_does_not_exist.bin"
    with open("missing_bin.gltf", "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def lines_and_triangles():
    # Primitive 0 is LINES (skipped with a warning), primitive 1 one triangle.
    g = Gltf()
    attrs = unit_triangle(g)
    g.doc["meshes"] = [{"name": "mixed", "primitives": [
        {"attributes": attrs, "indices": g.indices([0, 1, 1, 2]), "mode": 1},
        {"attributes": attrs}]}]
    g.single_node_scene()
    g.write("lines_and_triangles.gltf")


def cubic_spline():
    # Keys at t = 0, 2; each key is (in-tangent, value, out-tangent). The importer keeps
    # the values (1,2,3) and (4,5,6). A rotation channel with non-unit quaternions is
    # stored normalised: (0,0,2,0) -> (0,0,1,0).
    g = Gltf()
    g.doc["meshes"] = [{"primitives": [{"attributes": unit_triangle(g)}]}]
    g.single_node_scene()
    t = g.times([0.0, 2.0])
    v = g.vec3([(9.0, 9.0, 9.0), (1.0, 2.0, 3.0), (-9.0, -9.0, -9.0),
                (7.0, 7.0, 7.0), (4.0, 5.0, 6.0), (-7.0, -7.0, -7.0)])
    r = g.accessor("ffff", [(0.0, 0.0, 0.0, 2.0), (0.0, 0.0, 2.0, 0.0)], "VEC4", FLOAT)
    g.doc["animations"] = [{"name": "spline", "samplers": [
        {"input": t, "output": v, "interpolation": "CUBICSPLINE"},
        {"input": t, "output": r}],
        "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}},
                     {"sampler": 1, "target": {"node": 0, "path": "rotation"}}]}]
    g.write("cubic_spline.gltf")


def bad_key_times():
    g = Gltf()
    g.doc["meshes"] = [{"primitives": [{"attributes": unit_triangle(g)}]}]
    g.single_node_scene()
    t = g.times([0.0, 1.0, 1.0])
    v = g.vec3([(0.0, 0.0, 0.0)] * 3)
    g.doc["animations"] = [{"samplers": [{"input": t, "output": v}],
                            "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]}]
    g.write("bad_key_times.gltf")


def unused_streams():
    # TEXCOORD_0, TANGENT and COLOR_0 given, but the material has no texture: the scene
    # stores positions and normals only.
    g = Gltf()
    attrs = unit_triangle(g)
    attrs["TEXCOORD_0"] = g.accessor("ff", [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)], "VEC2", FLOAT)
    attrs["TANGENT"] = g.accessor("ffff", [(1.0, 0.0, 0.0, 1.0)] * 3, "VEC4", FLOAT)
    attrs["COLOR_0"] = g.vec3([(1.0, 0.0, 0.0)] * 3)
    g.doc["materials"] = [{"name": "plain", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1.0]}}]
    g.doc["meshes"] = [{"primitives": [{"attributes": attrs, "material": 0}]}]
    g.single_node_scene()
    g.write("unused_streams.gltf")


def normal_map():
    # Material 0: baseColor, normal and occlusion all from one image -> two textures
    # (sRGB colour, linear data; occlusion shares the linear entry). Primitive 0 has uvs
    # (u along +x, v along +y, so dP/du = +x and the generated tangent is (1,0,0), w = -1
    # because glTF's bitangent points towards decreasing v). Primitive 1 has no uvs
    # (zeros) and material 1 is untextured. Normal scale 0.5, occlusion strength 0.25,
    # alpha MASK at 0.3, double-sided.
    g = Gltf()
    attrs = unit_triangle(g)
    attrs["TEXCOORD_0"] = g.accessor("ff", [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)], "VEC2", FLOAT)
    tex = g.image(png_1x1([128, 128, 255, 255]))
    g.doc["materials"] = [
        {"name": "bumpy", "pbrMetallicRoughness": {"baseColorTexture": {"index": tex}, "metallicFactor": 0.25,
                                                   "roughnessFactor": 0.75},
         "normalTexture": {"index": tex, "scale": 0.5}, "occlusionTexture": {"index": tex, "strength": 0.25},
         "alphaMode": "MASK", "alphaCutoff": 0.3, "doubleSided": True},
        {"name": "flat", "emissiveFactor": [1.0, 0.5, 0.25]}]
    g.doc["meshes"] = [{"primitives": [{"attributes": attrs, "material": 0},
                                       {"attributes": unit_triangle(g), "material": 1}]}]
    g.single_node_scene()
    g.write("normal_map.gltf")


def interleaved_sparse():
    # One interleaved bufferView (stride 16): position float3 + TEXCOORD_0 as normalized
    # ushort2 (65535 -> 1.0). POSITION is sparse: vertex 2 is replaced by (0, 2, 0).
    # Indices are uint32.
    g = Gltf()
    rows = [((0.0, 0.0, 0.0), (0, 0)), ((1.0, 0.0, 0.0), (65535, 0)), ((0.0, 1.0, 0.0), (0, 65535))]
    data = b"".join(struct.pack("<fffHH", *p, *uv) for p, uv in rows)
    view = g.view(data, ARRAY_BUFFER, stride=16)
    g.doc["accessors"].append({"bufferView": view, "byteOffset": 0, "componentType": FLOAT, "count": 3,
                               "type": "VEC3", "min": [0, 0, 0], "max": [1, 2, 0],
                               "sparse": {"count": 1,
                                          "indices": {"bufferView": g.view(struct.pack("<H", 2)),
                                                      "componentType": USHORT},
                                          "values": {"bufferView": g.view(struct.pack("<fff", 0.0, 2.0, 0.0))}}})
    pos = len(g.doc["accessors"]) - 1
    g.doc["accessors"].append({"bufferView": view, "byteOffset": 12, "componentType": USHORT, "normalized": True,
                               "count": 3, "type": "VEC2"})
    uv = len(g.doc["accessors"]) - 1
    tex = g.image(png_1x1([255, 0, 0, 255]))
    g.doc["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": tex}}}]
    g.doc["meshes"] = [{"primitives": [{"attributes": {"POSITION": pos, "NORMAL": g.vec3([UP] * 3), "TEXCOORD_0": uv},
                                        "indices": g.indices([0, 1, 2], UINT), "material": 0}]}]
    g.single_node_scene()
    g.write("interleaved_sparse.gltf")


def schema_warnings():
    # Schema violations a sensible bake survives (docs/baker/lfd-bake.md "Validation"): a metallic
    # factor above 1 (clamped), a node name that is a number (ignored). lfd-bake warns;
    # lfd-bake --strict refuses the file.
    g = Gltf()
    g.doc["materials"] = [{"pbrMetallicRoughness": {"metallicFactor": 1.5}}]
    g.doc["meshes"] = [{"primitives": [{"attributes": unit_triangle(g), "material": 0}]}]
    g.single_node_scene()
    g.doc["nodes"][0]["name"] = 7
    g.write("schema_warnings.gltf")


def schema_error():
    # assimp's wrongTypes/badObject.gltf in small: pbrMetallicRoughness is an array.
    g = Gltf()
    g.doc["materials"] = [{"pbrMetallicRoughness": ["not an object"]}]
    g.doc["meshes"] = [{"primitives": [{"attributes": unit_triangle(g), "material": 0}]}]
    g.single_node_scene()
    g.write("schema_error.gltf")


def materials_and_lights():
    # KHR_texture_transform, KHR_materials_unlit and KHR_lights_punctual, all required: a
    # unit quad (u along +x, v along +y) of two primitives on node 0.
    # Primitive 0 (material "tiled"): base colour scaled (4, 2) - area scale 8 -, rotated
    # 0.5 rad, offset (0.5, 0.25); normal map with texCoord 1, overridden to 0 by the
    # extension (so usable), offset only. Primitive 1 (material "sticker"): unlit, its base
    # colour untransformed. Lights: directional "sun" (lux 3) on node 1, a child of node 0;
    # point "bulb" (range 4, unnamed in the scene: "light 1") on node 2; spot "cone"
    # (inner 0.2, outer 0.6) on nodes 3 and 4 (two instances); node 5 carries the sun but
    # is in no scene: dropped with a warning.
    g = Gltf()
    pts = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.0, 1.0, 0.0)]
    uvs = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    attrs = {"POSITION": g.positions(pts), "NORMAL": g.vec3([UP] * 4),
             "TEXCOORD_0": g.accessor("ff", uvs, "VEC2", FLOAT, ARRAY_BUFFER)}
    colour = g.image(png_1x1([200, 100, 50, 255]))
    bumps = g.image(png_1x1([128, 128, 255, 255]))
    g.doc["materials"] = [
        {"name": "tiled",
         "pbrMetallicRoughness": {"baseColorTexture": {"index": colour, "extensions": {"KHR_texture_transform": {
             "offset": [0.5, 0.25], "rotation": 0.5, "scale": [4.0, 2.0]}}}},
         "normalTexture": {"index": bumps, "texCoord": 1, "extensions": {"KHR_texture_transform": {
             "offset": [0.0, 0.5], "texCoord": 0}}}},
        {"name": "sticker", "pbrMetallicRoughness": {"baseColorTexture": {"index": colour}},
         "extensions": {"KHR_materials_unlit": {}}}]
    g.doc["meshes"] = [{"name": "quad", "primitives": [
        {"attributes": attrs, "indices": g.indices([0, 1, 2]), "material": 0},
        {"attributes": attrs, "indices": g.indices([0, 2, 3]), "material": 1}]}]
    names = ["KHR_texture_transform", "KHR_materials_unlit", "KHR_lights_punctual"]
    g.doc["extensionsUsed"] = names
    g.doc["extensionsRequired"] = names
    g.doc["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "sun", "type": "directional", "color": [1.0, 0.95, 0.8], "intensity": 3.0},
        {"type": "point", "color": [0.2, 0.4, 1.0], "intensity": 50.0, "range": 4.0},
        {"name": "cone", "type": "spot", "intensity": 400.0,
         "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.6}}]}}

    def light(name, index, **trs):
        return dict({"name": name, "extensions": {"KHR_lights_punctual": {"light": index}}}, **trs)
    g.doc["nodes"] = [{"name": "quad", "mesh": 0, "children": [1]},
                      light("sun node", 0, rotation=[-0.7071068, 0.0, 0.0, 0.7071068]),
                      light("bulb node", 1, translation=[0.5, 0.5, 1.0]),
                      light("spot left", 2, translation=[-1.0, 0.0, 2.0]),
                      light("spot right", 2, translation=[2.0, 0.0, 2.0]),
                      light("unused sun", 0)]
    g.doc["scenes"] = [{"nodes": [0, 2, 3, 4]}]
    g.doc["scene"] = 0
    g.write("materials_and_lights.gltf")


def malformed():
    with open("malformed.gltf", "w") as f:
        f.write('{"asset": {"version": "2.0"}, "meshes": [\n')


if __name__ == "__main__":
    for case in [strip, fan, no_normals, hierarchy, sheared, recursive, accessor_out_of_bounds,
                 index_out_of_range, webp_fallback, lambda: basisu(False), lambda: basisu(True),
                 lambda: quantized_normals(False), lambda: quantized_normals(True), missing_bin, lines_and_triangles, cubic_spline,
                 bad_key_times, unused_streams, normal_map, interleaved_sparse, schema_warnings, schema_error,
                 materials_and_lights, malformed]:
        case()
