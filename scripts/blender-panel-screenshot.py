# SPDX-License-Identifier: MIT
"""Screenshot of the add-on's panel (docs/blender-panel.png), Blender with its UI under Xvfb:

    PATH=build/baker:build/player:$PATH LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -s "-screen 0 1600x1000x24" \
        blender --factory-startup -p 0 0 1600 1000 --python scripts/blender-panel-screenshot.py -- OUT.png

Registers the add-on from blender/ (no install), turns the 3D viewport into a Properties
editor on the Scene tab with the panel first, bakes the factory cube once (so the panel
shows a result line) and saves that area. (bpy.ops.screen.screen_full_area from a timer
crashes Blender 3.4 under Xvfb, hence the area change.)"""

import os
import sys

import bpy

out = os.path.abspath(sys.argv[sys.argv.index("--") + 1] if "--" in sys.argv else "blender-panel.png")
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "blender"))
import lfd_blender  # noqa: E402

bpy.context.preferences.view.show_splash = False
lfd_blender.register()


def properties_area():
    win = bpy.context.window_manager.windows[0]
    return win, max(win.screen.areas, key=lambda a: a.width * a.height)


def step1():
    scene = bpy.context.scene
    scene.lfd.output_dir = "/tmp/lfd_panel_shot/"
    scene.lfd.profile_preset = next(i[0] for i in lfd_blender.properties.preset_items(scene.lfd, None)
                                    if "looking_glass" in i[0])
    scene.render.filepath = "//render/"
    win, area = properties_area()
    area.type = "PROPERTIES"
    bpy.app.timers.register(step1b, first_interval=0.5)  # the new editor exists after a redraw
    return None


def step1b():
    win, area = properties_area()
    area.spaces.active.context = "SCENE"
    with bpy.context.temp_override(window=win):
        bpy.ops.lfd.bake("INVOKE_DEFAULT")
    return None


def step2():
    win, area = properties_area()
    for a in win.screen.areas:
        a.tag_redraw()
    bpy.app.timers.register(step3, first_interval=1.0)
    return None


def crop_to_panel(path, area):
    """Keeps the rows from the panel's header down (Blender's built-in Scene panels above it
    take a fixed 322 px at UI scale 1)."""
    import numpy as np
    img = bpy.data.images.load(path)
    w, h = img.size
    px = np.empty(w * h * 4, dtype=np.float32)
    img.pixels.foreach_get(px)
    keep = h - 322  # image rows run bottom-up
    out_img = bpy.data.images.new("panel", w, keep, alpha=False)
    out_img.pixels.foreach_set(px.reshape(h, w, 4)[:keep].ravel())
    out_img.filepath_raw = path
    out_img.file_format = "PNG"
    bpy.context.scene.render.image_settings.compression = 100
    out_img.save()


def step3():
    win, area = properties_area()
    with bpy.context.temp_override(window=win, area=area):
        bpy.ops.screen.screenshot_area(filepath=out)
    crop_to_panel(out, area)
    print("wrote", out, flush=True)
    bpy.ops.wm.quit_blender()
    return None


bpy.app.timers.register(step1, first_interval=1.5)
bpy.app.timers.register(step2, first_interval=8.0)
