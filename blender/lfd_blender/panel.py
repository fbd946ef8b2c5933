# SPDX-License-Identifier: MIT
"""Properties > Scene > Light Field Display."""

import os

import bpy

from . import preview_operator, tools


class SCENE_PT_lfd(bpy.types.Panel):
    bl_label = "Light Field Display"
    bl_idname = "SCENE_PT_lfd"
    bl_space_type = "PROPERTIES"
    bl_region_type = "WINDOW"
    bl_context = "scene"

    def draw(self, context):
        s = context.scene.lfd
        layout = self.layout
        layout.use_property_split = True
        layout.use_property_decorate = False

        col = layout.column()
        col.prop(s, "tools_dir")
        ok, text = tools.tools_status(bpy.path.abspath(s.tools_dir) if s.tools_dir else "")
        row = col.row()
        row.alert = not ok
        row.label(text=("Tools found" if ok else text[:110]), icon="CHECKMARK" if ok else "ERROR")

        col = layout.column(heading="Display")
        col.prop(s, "profile_preset")
        if s.profile_preset == "FILE" or (s.display_profile and s.profile_preset == "BUILTIN"):
            col.prop(s, "display_profile")

        box = layout.box()
        box.label(text="Bake", icon="MESH_DATA")
        col = box.column()
        col.prop(s, "export_scope")
        col.prop(s, "max_edge_px")
        col.prop(s, "simplify")
        col.prop(s, "texture_compression")
        col.prop(s, "threads")
        col.prop(s, "output_dir")
        col.operator("lfd.bake", icon="EXPORT")

        box = layout.box()
        box.label(text="Preview", icon="HIDE_OFF")
        col = box.column()
        col.prop(s, "renderer")
        col.prop(s, "fullscreen")
        if s.fullscreen:
            col.prop(s, "monitor")
        row = col.row(align=True)
        row.operator("lfd.preview", icon="PLAY")
        if preview_operator.preview_running():
            row.operator("lfd.stop_preview", icon="CANCEL", text="")

        box = layout.box()
        box.label(text="Render to " + (context.scene.render.filepath or "//"), icon="RENDER_STILL")
        grid = box.grid_flow(columns=2, even_columns=True, align=True)
        for kind, label in (("QUILT", "Quilt"), ("EIA", "EIA")):
            for frames, suffix in (("CURRENT", ""), ("RANGE", " (range)")):
                op = grid.operator("lfd.render", text=label + suffix)
                op.kind, op.frame_range = kind, frames
        op = box.operator("lfd.render", text="Quilt video (range)", icon="FILE_MOVIE")
        op.kind, op.frame_range = "VIDEO", "RANGE"
        if s.last_message:
            box.label(text=s.last_message[:120], icon="INFO")


classes = (SCENE_PT_lfd,)
