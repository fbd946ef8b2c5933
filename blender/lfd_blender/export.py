# SPDX-License-Identifier: MIT
"""The scene (or the active collection) as a .glb through Blender's own glTF exporter,
with the options that keep animation, skins and morph targets."""

import time

import bpy

# Times in the file are Blender frame / scene fps (the exporter's convention), so Blender
# frame f is lfd-play's frame f at --fps scene.render.fps.
EXPORT_OPTIONS = dict(
    export_format="GLB",
    export_yup=True,
    export_apply=False,           # modifiers applied would drop shape keys; armatures stay skins
    export_texcoords=True,
    export_normals=True,
    export_tangents=False,
    export_materials="EXPORT",
    export_cameras=False,
    export_lights=True,           # KHR_lights_punctual: the baker reads them
    export_animations=True,
    export_frame_range=True,
    export_force_sampling=True,
    export_nla_strips=False,      # one animation with every object's active action
    export_current_frame=False,
    export_skins=True,
    export_all_influences=False,
    export_morph=True,
    export_morph_normal=True,
    export_morph_tangent=False,
    export_extras=False,
    export_animation_mode="ACTIVE_ACTIONS",  # Blender 3.6+: the same as export_nla_strips=False
    export_anim_slide_to_zero=False,         # Blender 3.6+: keep time = frame / fps
)


def supported_options(options):
    """The options this Blender's exporter has (names come and go between versions)."""
    known = set(bpy.ops.export_scene.gltf.get_rna_type().properties.keys())
    return {k: v for k, v in options.items() if k in known}


def export_glb(context, path, scope):
    """Writes path; returns the seconds it took. Raises RuntimeError with the exporter's text."""
    options = supported_options(EXPORT_OPTIONS)
    if scope == "COLLECTION":
        options.update(supported_options(dict(use_active_collection=True, use_active_collection_with_nested=True)))
    t0 = time.perf_counter()
    with context.temp_override(scene=context.scene) if hasattr(context, "temp_override") else _null():
        result = bpy.ops.export_scene.gltf(filepath=path, check_existing=False, **options)
    if "FINISHED" not in result:
        raise RuntimeError(f"the glTF exporter did not finish ({', '.join(result)})")
    return time.perf_counter() - t0


class _null:
    def __enter__(self):
        return self

    def __exit__(self, *args):
        return False
