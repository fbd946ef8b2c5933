# SPDX-License-Identifier: MIT
"""lfd-bake's output as Blender reports: warnings and errors one line each (the glTF path
translated back to the Blender object where it can be), progress lines as a fraction."""

import json
import re
import struct

_MESSAGE = re.compile(r"^(?:lfd-bake|lfd-play): (warning|error): (.*)$")
_PATH = re.compile(r"\b(meshes|nodes|materials|accessors|textures|images|animations|skins)\[(\d+)\]")
_COUNT = re.compile(r"(\d+)\s*/\s*(\d+)")

# Stages of a bake in the order lfd-bake prints them, with the share of the bar each ends at.
_STAGES = (("import", 0.15), ("framing", 0.2), ("simplification", 0.3), ("tessellation", 0.6),
           ("textures", 0.95))


def read_gltf_json(path):
    """The JSON of a .glb or .gltf file, or None."""
    try:
        with open(path, "rb") as f:
            data = f.read()
        if data[:4] == b"glTF":
            length, kind = struct.unpack_from("<II", data, 12)
            return json.loads(data[20:20 + length].decode("utf-8")) if kind == 0x4E4F534A else None
        return json.loads(data.decode("utf-8"))
    except (OSError, ValueError, struct.error):
        return None


class GltfNames:
    """Blender names for glTF indices: the exporter names nodes after objects (and bones),
    meshes after mesh data, materials, images and animations after theirs."""

    def __init__(self, doc):
        self.doc = doc or {}

    def _name(self, kind, i):
        items = self.doc.get(kind, [])
        return items[i].get("name") if 0 <= i < len(items) else None

    def _objects_of_mesh(self, m):
        return [n.get("name", f"nodes[{k}]") for k, n in enumerate(self.doc.get("nodes", [])) if n.get("mesh") == m]

    def _mesh_of_accessor(self, a):
        for m, mesh in enumerate(self.doc.get("meshes", [])):
            for p in mesh.get("primitives", []):
                refs = list(p.get("attributes", {}).values()) + [p.get("indices")]
                for t in p.get("targets", []):
                    refs += list(t.values())
                if a in refs:
                    return m
        return None

    def describe(self, kind, i):
        if kind == "accessors":
            m = self._mesh_of_accessor(i)
            return self.describe("meshes", m) if m is not None else None
        if kind == "meshes":
            objects = self._objects_of_mesh(i)
            mesh = self._name("meshes", i)
            if objects:
                return "object " + ", ".join(f"'{o}'" for o in objects) + (f" (mesh '{mesh}')" if mesh else "")
            return f"mesh '{mesh}'" if mesh else None
        label = {"nodes": "object", "materials": "material", "images": "image", "textures": "texture",
                 "animations": "action", "skins": "armature"}[kind]
        if kind == "textures":
            tex = self.doc.get("textures", [])
            src = tex[i].get("source") if 0 <= i < len(tex) else None
            name = self._name("images", src) if src is not None else None
        elif kind == "skins":
            skins = self.doc.get("skins", [])
            skel = skins[i].get("skeleton") if 0 <= i < len(skins) else None
            name = self._name("nodes", skel) if skel is not None else self._name("skins", i)
        else:
            name = self._name(kind, i)
        return f"{label} '{name}'" if name else None

    def translate(self, text):
        """text with the Blender name of its first glTF path appended, where known."""
        for match in _PATH.finditer(text):
            what = self.describe(match.group(1), int(match.group(2)))
            if what:
                return f"{text} [Blender: {what}]"
        return text


def classify(line, from_stderr):
    """('ERROR'|'WARNING'|'INFO', text) for one line of a tool's output."""
    m = _MESSAGE.match(line)
    if m:
        return ("ERROR" if m.group(1) == "error" else "WARNING"), m.group(2)
    if line.startswith(("lfd-bake: ", "lfd-play: ")):
        return ("ERROR" if from_stderr else "INFO"), line.split(": ", 1)[1]
    return ("WARNING" if from_stderr else "INFO"), line


def strip_file(text, gltf_path):
    """'FILE: rest' -> 'rest' when FILE is the exported glTF (the report names the scene)."""
    for prefix in (gltf_path + ": ",):
        if text.startswith(prefix):
            return text[len(prefix):]
    return text


def bake_progress(line):
    """(fraction, status) for a progress line of lfd-bake, or None."""
    for stage, (name, end) in enumerate(_STAGES):
        if line.startswith(name + ":"):
            start = _STAGES[stage - 1][1] if stage else 0.0
            m = _COUNT.search(line)
            fraction = end
            if m and int(m.group(2)) > 0:
                fraction = start + (end - start) * min(1.0, int(m.group(1)) / int(m.group(2)))
            return fraction, line[:120]
    return None
