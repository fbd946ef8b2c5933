# SPDX-License-Identifier: MIT
"""Scene.lfd: where the tools are, the display, bake options, output folder, preview and
render options. Paths may be Blender-relative ('//lfd/')."""

import os

import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty, StringProperty

from . import tools

ADDON_DIR = os.path.dirname(os.path.abspath(__file__))
_preset_cache = {"key": None, "items": [], "paths": {}}  # Blender keeps no reference to dynamic enum items


def preset_items(self, context):
    """BUILTIN, one item per shipped profile (identifier = its file name), FILE. The same list
    object is returned while the profiles found stay the same (Blender reads its strings later)."""
    tool_paths = [tools.find_tool(n, bpy.path.abspath(self.tools_dir) if self.tools_dir else "")
                  for n in ("lfd-bake", "lfd-play")]
    found = tools.shipped_profiles(tool_paths, ADDON_DIR)
    key = tuple(found)
    if key != _preset_cache["key"]:
        items = [("BUILTIN", "Prototype (built in)", "The paper's prototype display, built into the tools", 0)]
        paths = {}
        for i, (path, label) in enumerate(found):
            ident = label[:60]
            paths[ident] = path
            items.append((ident, label, path, i + 1))
        items.append(("FILE", "File...", "A display profile JSON or a Looking Glass visual.json, chosen below",
                      len(items)))
        _preset_cache.update(key=key, items=items, paths=paths)
    return _preset_cache["items"]


def preset_changed(self, context):
    if self.profile_preset == "BUILTIN":
        self.display_profile = ""
    elif self.profile_preset != "FILE":
        self.display_profile = _preset_cache["paths"].get(self.profile_preset, "")


class LfdSettings(bpy.types.PropertyGroup):
    tools_dir: StringProperty(
        name="Tools folder", subtype="DIR_PATH", default="",
        description="Folder with lfd-bake and lfd-play (several separated by ':'); empty: found on PATH")
    profile_preset: EnumProperty(
        name="Display", items=preset_items, update=preset_changed,
        description="A shipped display profile, the built-in prototype, or a file")
    display_profile: StringProperty(
        name="Profile file", subtype="FILE_PATH", default="",
        description="Display profile JSON or Looking Glass visual.json; empty: the built-in prototype")
    export_scope: EnumProperty(
        name="Export", default="SCENE",
        items=(("SCENE", "Scene", "Every object of the scene"),
               ("COLLECTION", "Active collection", "The active collection (and the collections inside it)")))
    max_edge_px: FloatProperty(
        name="Tessellation bound", default=100.0, min=1.0, soft_max=1000.0,
        description="Split triangles whose edges span more view pixels than this (lfd-bake --max-edge-px)")
    simplify: FloatProperty(
        name="Simplify", default=0.25, min=0.0, soft_max=4.0,
        description="Merge triangles finer than the display resolves, moving the surface by at most this many "
                    "view pixels; 0: off (lfd-bake --simplify)")
    texture_compression: EnumProperty(
        name="Textures", default="bc",
        items=(("bc", "Block compressed", "BC1/BC3/BC4/BC5 (lfd-bake --texture-compression bc)"),
               ("none", "Uncompressed", "RGBA8 (--texture-compression none)")))
    threads: IntProperty(name="Threads", default=0, min=0, max=256,
                         description="Bake threads; 0: every core (lfd-bake --threads)")
    output_dir: StringProperty(
        name="Output folder", subtype="DIR_PATH", default="//lfd/",
        description="Where the exported glTF and the baked pack go ('//': beside the .blend file; the "
                    "system's temporary folder for an unsaved file)")
    renderer: EnumProperty(
        name="Renderer", default="mvr",
        items=(("mvr", "Raster (mvr)", "One raster pass per view"),
               ("mvr-layered", "Raster, layered", "One instanced pass for all views"),
               ("lfdpr", "LFDPR", "Light field display point rendering")))
    fullscreen: BoolProperty(name="Fullscreen on the display", default=False,
                             description="Preview pixel for pixel on the display's monitor (lfd-play --fullscreen)")
    monitor: StringProperty(name="Monitor", default="",
                            description="Monitor index or name for fullscreen; empty: the one matching the panel")
    last_pack: StringProperty(name="Last pack", default="", options={"SKIP_SAVE"})
    last_message: StringProperty(name="Last message", default="", options={"SKIP_SAVE"})
    last_outputs: StringProperty(name="Last outputs", default="", options={"SKIP_SAVE"},
                                 description="Files the last render wrote, one per line")


classes = (LfdSettings,)
