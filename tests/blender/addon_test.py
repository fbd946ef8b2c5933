# SPDX-License-Identifier: MIT
"""The Blender add-on end to end, headless (CTest BlenderAddon):

    blender -b --factory-startup --python-exit-code 1 --python tests/blender/addon_test.py -- \
        --zip build/blender/lfd_blender.zip --tools-dir build/baker:build/player --work DIR

Installs the add-on from its zip, builds a scene in Python (a textured object, an animated
object, a metal sphere, a skinned object), bakes it through bpy.ops.lfd.bake() and checks
the pack verifies (lfd-bake --inspect) and equals, byte for byte, the pack lfd-bake makes
from the same exported glTF; renders quilts of frames 1..3 through bpy.ops.lfd.render()
and checks they differ pairwise and equal lfd-play's own quilts of those frames, an EIA of
the current frame against lfd-play's, and a quilt video; bad settings (missing tools, a
too-old tool, an unreadable or invalid display profile) give one ERROR report and no
Python traceback; the glTF paths of lfd-bake's messages name the Blender objects; the
add-on's own overhead (export + launching lfd-bake) is under 2 s."""

import argparse
import os
import re
import shutil
import subprocess
import sys
import time

import addon_utils
import bpy
import numpy as np

args = argparse.ArgumentParser()
args.add_argument("--zip", required=True)
args.add_argument("--tools-dir", required=True)
args.add_argument("--work", required=True)
args = args.parse_args(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else [])

failures = []


def check(ok, what):
    print(("ok: " if ok else "FAILED: ") + what, flush=True)
    if not ok:
        failures.append(what)
    return ok


def tool(name):
    for d in args.tools_dir.split(os.pathsep):
        if os.path.isfile(os.path.join(d, name)):
            return os.path.join(d, name)
    raise SystemExit(f"{name} not in {args.tools_dir}")


# Small views so the test runs in seconds on llvmpipe: 8 views of 48x36 on a 384x216 panel.
TINY_PROFILE = """{
  "format": "lfd-display-profile/1", "name": "blender-test-tiny",
  "panel_width": 384, "panel_height": 216, "screen_width_mm": 34.54, "screen_height_mm": 19.43,
  "subpixel_order": "RGB", "lens_width_mm": 0.72, "lens_tilt_deg": -9.66,
  "view_count": 8, "view_width": 48, "view_height": 36, "view_cone_deg": 40.0, "viewing_distance_mm": 300.0
}"""


def run_op(op, **kw):
    """(result, error text or None) of an operator called from Python: an ERROR report
    reaches Python as RuntimeError('Error: ...'), a crash inside the add-on as a traceback."""
    try:
        return op(**kw), None
    except RuntimeError as e:
        return {"CANCELLED"}, str(e)


def pixels(path):
    img = bpy.data.images.load(path, check_existing=False)
    a = np.empty(img.size[0] * img.size[1] * img.channels, dtype=np.float32)
    img.pixels.foreach_get(a)
    size = tuple(img.size)
    bpy.data.images.remove(img)
    return size, a


def build_scene(work):
    for obj in list(bpy.data.objects):  # the factory scene's cube, camera and light
        bpy.data.objects.remove(obj)
    scene = bpy.context.scene
    scene.name = "AddonTest"
    scene.frame_start, scene.frame_end, scene.frame_current = 1, 3, 2
    scene.render.fps = 24

    # textured plane (a checker image saved as PNG)
    n = 64
    img = bpy.data.images.new("Checker", n, n)
    ys, xs = np.mgrid[0:n, 0:n]
    c = (((xs // 8) + (ys // 8)) % 2).astype(np.float32)
    rgba = np.stack([c, 0.3 + 0.4 * c, 1.0 - c, np.ones_like(c)], axis=-1).ravel()
    img.pixels.foreach_set(rgba)
    img.filepath_raw = os.path.join(work, "checker.png")
    img.file_format = "PNG"
    img.save()
    bpy.ops.mesh.primitive_plane_add(size=3.0, location=(0, 0, -1))
    plane = bpy.context.object
    plane.name = "TexturedFloor"
    mat = bpy.data.materials.new("CheckerMaterial")
    mat.use_nodes = True
    tex = mat.node_tree.nodes.new("ShaderNodeTexImage")
    tex.image = img
    mat.node_tree.links.new(tex.outputs["Color"], mat.node_tree.nodes["Principled BSDF"].inputs["Base Color"])
    plane.data.materials.append(mat)

    # animated cube: moves across the view over frames 1..3
    bpy.ops.mesh.primitive_cube_add(size=0.6, location=(-1, 0, 0))
    cube = bpy.context.object
    cube.name = "MovingCube"
    red = bpy.data.materials.new("Red")
    red.diffuse_color = (0.9, 0.1, 0.1, 1)
    red.use_nodes = True
    red.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0.9, 0.1, 0.1, 1)
    cube.data.materials.append(red)
    for frame, x in ((1, -1.0), (3, 1.0)):
        cube.location.x = x
        cube.keyframe_insert("location", frame=frame)

    # metal sphere
    bpy.ops.mesh.primitive_uv_sphere_add(radius=0.5, location=(0.6, 0.8, 0))
    sphere = bpy.context.object
    sphere.name = "MetalSphere"
    metal = bpy.data.materials.new("Metal")
    metal.use_nodes = True
    bsdf = metal.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Metallic"].default_value = 1.0
    bsdf.inputs["Roughness"].default_value = 0.2
    sphere.data.materials.append(metal)

    # skinned cylinder: two bones, the upper one bent by frame 3
    bpy.ops.object.armature_add(location=(-0.8, -0.8, -0.5))
    arm = bpy.context.object
    arm.name = "Rig"
    bpy.ops.object.mode_set(mode="EDIT")
    b0 = arm.data.edit_bones[0]
    b0.name = "Lower"
    b0.head, b0.tail = (0, 0, 0), (0, 0, 0.5)
    b1 = arm.data.edit_bones.new("Upper")
    b1.head, b1.tail, b1.parent = (0, 0, 0.5), (0, 0, 1.0), b0
    bpy.ops.object.mode_set(mode="OBJECT")
    bpy.ops.mesh.primitive_cylinder_add(radius=0.15, depth=1.0, location=(-0.8, -0.8, 0.0), vertices=12)
    limb = bpy.context.object
    limb.name = "SkinnedLimb"
    bpy.ops.object.mode_set(mode="EDIT")
    bpy.ops.mesh.subdivide(number_cuts=4)
    bpy.ops.object.mode_set(mode="OBJECT")
    lower, upper = limb.vertex_groups.new(name="Lower"), limb.vertex_groups.new(name="Upper")
    for v in limb.data.vertices:
        w = min(1.0, max(0.0, (v.co.z + 0.5)))
        lower.add([v.index], 1.0 - w, "REPLACE")
        upper.add([v.index], w, "REPLACE")
    limb.parent = arm
    limb.matrix_parent_inverse = arm.matrix_world.inverted()
    mod = limb.modifiers.new("Armature", "ARMATURE")
    mod.object = arm
    pb = arm.pose.bones["Upper"]
    pb.rotation_mode = "XYZ"
    for frame, angle in ((1, 0.0), (3, 1.0)):
        pb.rotation_euler.x = angle
        pb.keyframe_insert("rotation_euler", frame=frame)

    bpy.ops.object.light_add(type="SUN", location=(0, 0, 3))
    scene.frame_set(2)
    return scene


def main():
    work = os.path.abspath(args.work)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    profile = os.path.join(work, "tiny.json")
    with open(profile, "w") as f:
        f.write(TINY_PROFILE)
    bake, play = tool("lfd-bake"), tool("lfd-play")

    # Install from the zip, as a user would (BLENDER_USER_SCRIPTS points into the build tree).
    t0 = time.perf_counter()
    bpy.ops.preferences.addon_install(filepath=os.path.abspath(args.zip), overwrite=True)
    addon_utils.enable("lfd_blender", default_set=True, handle_error=None)
    check(addon_utils.check("lfd_blender")[1], "the add-on installs from its zip and enables")
    check(hasattr(bpy.ops.lfd, "bake") and hasattr(bpy.ops.lfd, "render"), "bpy.ops.lfd.bake/preview/render exist")
    print(f"install: {time.perf_counter() - t0:.2f} s")

    scene = build_scene(work)
    s = scene.lfd
    s.tools_dir = args.tools_dir
    s.display_profile = profile
    s.output_dir = os.path.join(work, "lfd") + os.sep
    s.threads = 2
    scene.render.filepath = os.path.join(work, "render") + os.sep

    # ---- the shipped profiles are offered (found from the build tree's source tree)
    from lfd_blender import properties
    idents = [i[0] for i in properties.preset_items(s, bpy.context)]
    check("looking_glass_portrait_visual" in idents and "BUILTIN" in idents and "FILE" in idents,
          f"the display menu offers the shipped profiles ({idents})")
    s.profile_preset = "looking_glass_portrait_visual"
    check(s.display_profile.endswith("looking_glass_portrait_visual.json") and os.path.isfile(s.display_profile),
          "choosing a shipped profile sets its file")
    s.profile_preset = "BUILTIN"
    check(s.display_profile == "", "the built-in prototype clears the file")
    s.display_profile = profile

    # ---- bad settings: one ERROR report each, never a traceback
    def expect_error(what, pattern, op=bpy.ops.lfd.bake, **kw):
        result, err = run_op(op, **kw)
        check(result == {"CANCELLED"} and err is not None and "Traceback" not in err
              and re.search(pattern, err) is not None, f"{what}: one error report ({err!r})")

    s.tools_dir = os.path.join(work, "no-such-dir")
    expect_error("missing tools", r"lfd-bake not found in .*no-such-dir")
    expect_error("missing tools (render)", r"not found", bpy.ops.lfd.render, kind="QUILT")
    fake = os.path.join(work, "old-tools")
    os.makedirs(fake)
    with open(os.path.join(fake, "lfd-bake"), "w") as f:
        f.write("#!/bin/sh\necho 'lfd-bake INPUT -o OUT [--display P]'\n")
    os.chmod(os.path.join(fake, "lfd-bake"), 0o755)
    s.tools_dir = fake
    expect_error("too-old lfd-bake", r"too old .*--simplify")
    s.tools_dir = args.tools_dir
    s.display_profile = os.path.join(work, "missing.json")
    expect_error("unreadable display profile", r"display profile .*missing\.json")
    bad = os.path.join(work, "bad.json")
    with open(bad, "w") as f:
        f.write('{"format": "lfd-display-profile/1", "panel_width": 0}')
    s.display_profile = bad
    expect_error("invalid display profile (refused by lfd-bake)", r"lfd-bake: .*bad\.json")
    s.display_profile = profile

    # ---- bake through the add-on; the same glTF through the CLI gives the same bytes
    result, err = run_op(bpy.ops.lfd.bake)
    check(result == {"FINISHED"} and err is None, f"bake finishes ({err})")
    print("bake:", s.last_message)
    glb, pack = os.path.join(work, "lfd", "AddonTest.glb"), os.path.join(work, "lfd", "AddonTest.lfdpack")
    check(os.path.isfile(pack) and s.last_pack == pack, "the pack is written to the output folder")
    inspect = subprocess.run([bake, "--inspect", pack], capture_output=True, text=True)
    check(inspect.returncode == 0, "lfd-bake --inspect verifies the pack")
    print(inspect.stdout)
    check("skin" in inspect.stdout.lower() or "deformer" in inspect.stdout.lower(),
          "the pack has the skinned limb's deformer")
    cli_dir = os.path.join(work, "cli")
    os.makedirs(cli_dir)
    shutil.copy(glb, cli_dir)  # the same file name: the pack records it
    cli_pack = os.path.join(cli_dir, "AddonTest.lfdpack")
    subprocess.run([bake, os.path.join(cli_dir, "AddonTest.glb"), "-o", cli_pack, "--display", profile,
                    "--quiet"], check=True)
    with open(pack, "rb") as a, open(cli_pack, "rb") as b:
        check(a.read() == b.read(), "the add-on's pack is byte-identical to lfd-bake's from the same glTF")

    m = re.search(r"export ([0-9.]+) s, launch ([0-9.]+) ms", s.last_message)
    if check(m is not None, "the bake reports its export and launch times"):
        export_s, launch_ms = float(m.group(1)), float(m.group(2))
        print(f"overhead: export {export_s:.3f} s + launch {launch_ms:.1f} ms")
        check(export_s + launch_ms / 1000 < 2.0, "the add-on's overhead (export + launch) is under 2 s")

    # ---- glTF paths in lfd-bake's messages name the Blender objects
    from lfd_blender import reports
    names = reports.GltfNames(reports.read_gltf_json(glb))
    doc = names.doc
    cube_mesh = next(n["mesh"] for n in doc["nodes"] if n.get("name") == "MovingCube")
    text = names.translate(f"meshes[{cube_mesh}].primitives[0]: something")
    check("object 'MovingCube'" in text, f"a mesh path names its object ({text})")
    acc = doc["meshes"][cube_mesh]["primitives"][0]["attributes"]["POSITION"]
    check("MovingCube" in names.translate(f"accessors[{acc}]: x"), "an accessor path names its object")
    check(reports.classify("lfd-bake: warning: x.glb: nodes[0]: y", True) == ("WARNING", "x.glb: nodes[0]: y"),
          "lfd-bake warnings become WARNING reports")
    p = reports.bake_progress("tessellation: mesh 'Cube': 50 / 100 triangles")
    check(p is not None and abs(p[0] - 0.45) < 1e-9, f"a tessellation progress line is half of its stage ({p})")

    # ---- a running step is cancelled: the process ends, the job says CANCELLED
    from lfd_blender import jobs
    step = jobs.ProcessStep("Sleeping", ["sleep", "30"])
    job = jobs.Job([step])
    job.poll()
    t0 = time.perf_counter()
    job.cancel()
    check(job.state == "CANCELLED" and step.proc.poll() is not None and time.perf_counter() - t0 < 5,
          "cancelling a job ends its process")

    # ---- preview: without a display lfd-play's refusal is the report; with one, a screenshot
    if os.environ.get("DISPLAY"):
        shot = os.path.join(work, "preview.png")
        result, err = run_op(bpy.ops.lfd.preview, screenshot=shot, frames=1)
        check(result == {"FINISHED"} and os.path.isfile(shot), f"preview saves a screenshot ({err})")
    else:
        expect_error("preview without a display", r"lfd-play|display|GLFW|X11", bpy.ops.lfd.preview)

    # ---- quilts of frames 1..3 (the render re-uses the current pack: no re-bake)
    mtime = os.path.getmtime(pack)
    t0 = time.perf_counter()
    result, err = run_op(bpy.ops.lfd.render, kind="QUILT", frame_range="RANGE")
    print(f"render quilts 1..3: {time.perf_counter() - t0:.2f} s: {s.last_message}")
    check(result == {"FINISHED"} and err is None, f"render of the range finishes ({err})")
    check(os.path.getmtime(pack) == mtime, "an unchanged scene is not baked again")
    outs = s.last_outputs.split("\n")
    # 8 views on a 16:9 panel: lfd-play's layout rule gives 3x3, the aspect the screen's
    names_ok = [re.search(rf"AddonTest_000{k}_qs3x3a1\.78\.png$", o) for k, o in zip((1, 2, 3), outs)]
    check(len(outs) == 3 and all(names_ok), f"three quilts with the vendor's naming ({outs})")
    if len(outs) == 3:
        imgs = [pixels(o) for o in outs]
        for i in range(3):
            for j in range(i + 1, 3):
                check(not np.array_equal(imgs[i][1], imgs[j][1]), f"quilt of frame {i + 1} differs from {j + 1}")
        direct = os.path.join(work, "direct")
        os.makedirs(direct)
        subprocess.run([play, pack, "--headless", "--display", profile, "--renderer", "mvr", "--no-turntable",
                        "--fps", "24", "--frames", "4", "--quilt", os.path.join(direct, "q.png"),
                        "--out", os.path.join(direct, "eia_%04d.png")], check=True, capture_output=True)
        for k in (1, 2, 3):
            ref = pixels(os.path.join(direct, f"q_{k:04d}_qs3x3a1.78.png"))
            got = imgs[k - 1]
            check(ref[0] == got[0] and np.array_equal(ref[1], got[1]),
                  f"frame {k}'s quilt equals lfd-play's (max diff {np.abs(ref[1] - got[1]).max() if ref[0] == got[0] else 'size'})")

        # ---- EIA of the current frame (2)
        result, err = run_op(bpy.ops.lfd.render, kind="EIA", frame_range="CURRENT")
        check(result == {"FINISHED"} and err is None, f"EIA render finishes ({err})")
        eia = os.path.join(work, "render", "AddonTest_eia_0002.png")
        if check(os.path.isfile(eia), "the EIA of the current frame is written"):
            ref, got = pixels(os.path.join(direct, "eia_0002.png")), pixels(eia)
            check(ref[0] == got[0] == (384, 216) and np.array_equal(ref[1], got[1]),
                  "the EIA equals lfd-play's for that frame")

    # ---- quilt video of the range
    result, err = run_op(bpy.ops.lfd.render, kind="VIDEO", frame_range="RANGE")
    check(result == {"FINISHED"} and err is None, f"quilt video finishes ({err})")
    video = os.path.join(work, "render", "AddonTest_qs3x3a1.78.mp4")
    check(os.path.isfile(video) and os.path.getsize(video) > 0, "the quilt video is written with the vendor's name")
    check(not [p for p in os.listdir(os.path.join(work, "render")) if p.startswith(".lfd-render-")],
          "no temporary folder is left behind")

    # ---- a changed scene is baked again before rendering
    bpy.data.objects["MetalSphere"].location.z += 0.3
    result, err = run_op(bpy.ops.lfd.render, kind="QUILT", frame_range="CURRENT")
    check(result == {"FINISHED"} and os.path.getmtime(pack) != mtime, "a changed scene is baked again")

    # ---- the active collection alone
    only = bpy.data.collections.new("OnlyThis")
    scene.collection.children.link(only)
    bpy.ops.mesh.primitive_monkey_add()
    monkey = bpy.context.object
    monkey.name = "LoneMonkey"
    for c in list(monkey.users_collection):
        c.objects.unlink(monkey)
    only.objects.link(monkey)
    bpy.context.view_layer.active_layer_collection = bpy.context.view_layer.layer_collection.children["OnlyThis"]
    s.export_scope = "COLLECTION"
    result, err = run_op(bpy.ops.lfd.bake)
    nodes = [n.get("name") for n in reports.read_gltf_json(glb).get("nodes", [])]
    check(result == {"FINISHED"} and nodes == ["LoneMonkey"], f"the active collection alone is exported ({nodes})")
    s.export_scope = "SCENE"

    # ---- a bad frame range is a report
    expect_error("empty frame range", r"frames 3\.\.1", bpy.ops.lfd.render, kind="QUILT", frame_range="RANGE",
                 frame_start=3, frame_end=1)


try:
    main()
except Exception as e:  # noqa: BLE001
    import traceback
    traceback.print_exc()
    failures.append(f"exception: {e}")
print(f"{len(failures)} failure(s)" + ("".join("\n  " + f for f in failures) if failures else ""), flush=True)
sys.exit(1 if failures else 0)
