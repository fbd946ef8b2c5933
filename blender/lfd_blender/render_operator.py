# SPDX-License-Identifier: MIT
"""LFD_OT_render: quilts, EIAs or a quilt video of the current frame or the frame range,
rendered headless by lfd-play into Blender's output path (render.filepath), with the
vendor's quilt naming NAME_qs{cols}x{rows}a{aspect}. Bakes first when the pack is not
current. Esc cancels (UI); in background mode the run completes."""

import glob
import os
import re
import shutil
import tempfile
import time

import bpy

from . import jobs, pipeline, reports

_QUILT = re.compile(r"_(\d{4})_(qs\d+x\d+(?:a[0-9.]+)?)\.png$")


def output_base(scene, fallback_name):
    """(folder, prefix) from render.filepath: '/tmp/' -> ('/tmp', scene name); '//out/shot_' -> ('out', 'shot')."""
    path = bpy.path.abspath(scene.render.filepath or "//")
    if path.startswith("//"):  # unsaved file
        path = os.path.join(tempfile.gettempdir(), path[2:])
    if path.endswith(os.sep) or os.path.isdir(path):
        return os.path.abspath(path), fallback_name
    prefix = os.path.basename(path).rstrip("#_.- ") or fallback_name
    return os.path.abspath(os.path.dirname(path)), prefix


class LFD_OT_render(bpy.types.Operator, pipeline.JobOperator):
    """Render quilts, EIAs or a quilt video headless with lfd-play into the output path (bakes first if needed)"""

    bl_idname = "lfd.render"
    bl_label = "Render"
    bl_options = {"REGISTER"}

    kind: bpy.props.EnumProperty(
        name="Kind", default="QUILT",
        items=(("QUILT", "Quilt", "Looking Glass quilt PNG per frame (NAME_FFFF_qsCxRaA.png)"),
               ("EIA", "EIA", "Elemental image array (panel image) PNG per frame"),
               ("VIDEO", "Quilt video", "The frames' quilts as an H.264 video (NAME_qsCxRaA.mp4)")))
    frame_range: bpy.props.EnumProperty(
        name="Frames", default="CURRENT",
        items=(("CURRENT", "Current frame", "The scene's current frame"),
               ("RANGE", "Frame range", "The scene's frame range (or frame_start..frame_end when set)")))
    frame_start: bpy.props.IntProperty(name="Start", default=-1, min=-1, options={"SKIP_SAVE"},
                                       description="First frame of RANGE; -1: the scene's")
    frame_end: bpy.props.IntProperty(name="End", default=-1, min=-1, options={"SKIP_SAVE"},
                                     description="Last frame of RANGE; -1: the scene's")

    def frames(self, scene):
        if self.frame_range == "CURRENT" and self.kind != "VIDEO":
            return scene.frame_current, scene.frame_current
        a = self.frame_start if self.frame_start >= 0 else scene.frame_start
        b = self.frame_end if self.frame_end >= 0 else scene.frame_end
        if self.frame_range == "CURRENT":  # a video of the current frame: one frame
            a = b = scene.frame_current
        return a, b

    def execute(self, context):
        self.init_job_state()
        scene = context.scene
        a, b = self.frames(scene)
        if a < 0 or b < a:
            return self.fail(context, f"frames {a}..{b}: lfd-play renders frames from 0 (the glTF's time "
                                      "0), so the range must start at 0 or later and not end before it starts")
        if self.kind == "VIDEO" and shutil.which("ffmpeg") is None:
            return self.fail(context, "a quilt video needs ffmpeg (not on PATH; install the Debian package "
                                      "'ffmpeg')")
        try:
            r = pipeline.Resolved(context, need=("lfd-bake", "lfd-play"))
            out_dir, prefix = output_base(scene, r.name)
            os.makedirs(out_dir, exist_ok=True)
            pipeline.export_scene(context, r, self)
        except OSError as e:
            return self.fail(context, f"output path {scene.render.filepath}: {e.strerror}")
        except (pipeline.SetupError, RuntimeError) as e:
            return self.fail(context, str(e))
        self.resolved, self.out_dir, self.prefix, self.range = r, out_dir, prefix, (a, b)
        self.tmp = tempfile.mkdtemp(prefix=".lfd-render-", dir=out_dir)
        self.outputs = []
        steps = [] if pipeline.pack_is_current(r) else [pipeline.bake_step(r, self)]
        steps.append(self.play_step(context, r, a, b))
        if self.kind == "VIDEO":
            steps.append(self.video_step(context, a, b))
        steps.append(jobs.FuncStep("Collecting", lambda: self.collect(a, b)))
        result = self.start_job(context, jobs.Job(steps, on_cleanup=self.cleanup))
        if result == {"CANCELLED"} and self.job is None:  # refused before it started
            self.cleanup("CANCELLED")
        return result

    # One lfd-play run: frame k is at time k / fps, the glTF time of Blender frame k, and
    # --first-frame a renders frames a..b alone, under their own numbers.
    def play_step(self, context, r, a, b):
        s = context.scene.lfd
        fps = context.scene.render.fps
        argv = [r.tools["lfd-play"], r.pack, "--headless", *r.display_args(), "--renderer", s.renderer,
                "--no-turntable", "--fps", f"{fps:g}"]
        quilt = self.kind in ("QUILT", "VIDEO")
        argv += ["--first-frame", str(a), "--frames", str(b - a + 1)]
        if a == b:
            if quilt:
                argv += ["--quilt", os.path.join(self.tmp, f"{self.prefix}_{a:04d}.png")]
            else:
                argv += ["--out", os.path.join(self.tmp, f"{self.prefix}_eia_{a:04d}.png")]
            expected = 1
        else:
            if quilt:
                argv += ["--quilt", os.path.join(self.tmp, f"{self.prefix}.png")]
            else:
                argv += ["--out", os.path.join(self.tmp, f"{self.prefix}_eia_%04d.png")]
            expected = b - a + 1
        errors = []

        def on_line(line, from_stderr):
            if from_stderr:
                level, text = reports.classify(line, True)
                (errors if level == "ERROR" else self.messages).append(
                    text if level == "ERROR" else (level, text))

        def on_exit(code):
            if code != 0:
                raise jobs.StepFailed("lfd-play: " + (errors[-1] if errors else f"failed (exit status {code})"))

        def progress():
            return len(glob.glob(os.path.join(self.tmp, "*.png"))) / expected

        self.status = f"frames {a}..{b}"
        return jobs.ProcessStep("Rendering", argv, on_line, on_exit, progress, weight=2.0)

    def quilts(self, a, b):
        found = {}
        for path in glob.glob(os.path.join(glob.escape(self.tmp), "*.png")):
            m = _QUILT.search(os.path.basename(path))
            if m and a <= int(m.group(1)) <= b:
                found[int(m.group(1))] = (path, m.group(2))
        return found

    def video_step(self, context, a, b):
        fps = context.scene.render.fps

        def argv():
            q = self.quilts(a, b)
            if len(q) != b - a + 1:
                raise jobs.StepFailed(f"lfd-play wrote {len(q)} quilts for frames {a}..{b}")
            layout = q[a][1]
            self.video = os.path.join(self.tmp, f"{self.prefix}_{layout}.mp4")
            pattern = os.path.join(self.tmp, f"{self.prefix}_%04d_{layout}.png")
            # lfd-play's own encoder settings (player/app/quilt_video.cpp)
            return ["ffmpeg", "-hide_banner", "-loglevel", "error", "-nostdin", "-y", "-framerate", f"{fps:g}",
                    "-start_number", str(a), "-i", pattern, "-frames:v", str(b - a + 1),
                    "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p", "-c:v", "libx264",
                    "-preset", "medium", "-crf", "15", "-movflags", "+faststart", "-f", "mp4", self.video]

        errors = []

        def on_exit(code):
            if code != 0:
                raise jobs.StepFailed("ffmpeg: " + (errors[-1] if errors else f"failed (exit status {code})"))

        return jobs.ProcessStep("Encoding", argv, lambda l, e: errors.append(l) if e else None, on_exit,
                                weight=0.5)

    def collect(self, a, b):
        if self.kind == "VIDEO":
            files = [self.video]
        elif self.kind == "QUILT":
            files = [p for _, (p, _) in sorted(self.quilts(a, b).items())]
        else:
            files = [os.path.join(self.tmp, f"{self.prefix}_eia_{f:04d}.png") for f in range(a, b + 1)]
        missing = [f for f in files if not os.path.isfile(f)]
        if missing or not files:
            raise jobs.StepFailed(f"lfd-play did not write {os.path.basename(missing[0]) if missing else 'anything'}")
        for f in files:
            target = os.path.join(self.out_dir, os.path.basename(f))
            os.replace(f, target)
            self.outputs.append(target)

    def cleanup(self, state):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def on_finished(self, context):
        a, b = self.range
        seconds = time.perf_counter() - self.t_start
        names = os.path.basename(self.outputs[0]) + (f" .. {os.path.basename(self.outputs[-1])}"
                                                     if len(self.outputs) > 1 else "")
        text = f"Wrote {len(self.outputs)} file(s) to {self.out_dir}: {names} (frames {a}..{b}, {seconds:.1f} s)"
        self.report({"INFO"}, text)
        s = context.scene.lfd
        s.last_message = text
        s.last_outputs = "\n".join(self.outputs)
        return {"FINISHED"}


classes = (LFD_OT_render,)
