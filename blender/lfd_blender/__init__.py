# SPDX-License-Identifier: MIT
"""LFD toolkit add-on: bake the scene with lfd-bake, preview it with lfd-play, render
quilts, EIAs and quilt videos for a light field display (docs/blender.md).

Scripting: settings on ``bpy.types.Scene.lfd`` (``output_dir``, ``display_profile``,
``tools_dir``, ...), operators ``bpy.ops.lfd.bake()``, ``bpy.ops.lfd.preview()`` and
``bpy.ops.lfd.render(kind='QUILT'|'EIA'|'VIDEO', frame_range='CURRENT'|'RANGE')``. In
background mode (``blender -b``) each runs to completion before returning.
"""

bl_info = {
    "name": "LFD light field display toolkit",
    "author": "LFDPR toolkit",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "Properties > Scene > Light Field Display",
    "description": "Bake with lfd-bake, preview with lfd-play, render quilts, EIAs and quilt videos",
    "category": "Import-Export",
}

if "bpy" in locals():  # add-on reload (F3 > Reload Scripts)
    import importlib
    for _m in (tools, reports, jobs, export, properties, pipeline, bake_operator, preview_operator,
               render_operator, panel):
        importlib.reload(_m)
else:
    from . import tools, reports, jobs, export, properties, pipeline, bake_operator, preview_operator, \
        render_operator, panel

import bpy  # noqa: E402

_classes = (
    *properties.classes,
    *bake_operator.classes,
    *preview_operator.classes,
    *render_operator.classes,
    *panel.classes,
)


def register():
    for cls in _classes:
        bpy.utils.register_class(cls)
    bpy.types.Scene.lfd = bpy.props.PointerProperty(type=properties.LfdSettings)


def unregister():
    preview_operator.stop_preview()
    del bpy.types.Scene.lfd
    for cls in reversed(_classes):
        bpy.utils.unregister_class(cls)
