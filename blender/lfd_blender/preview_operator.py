# SPDX-License-Identifier: MIT
"""LFD_OT_preview: lfd-play on the baked pack in a window, or fullscreen on the display's
monitor. Baking again restarts it on the new pack (lfd-play has no reload of its own)."""

import subprocess
import tempfile
import time

import bpy

from . import jobs, pipeline

_preview = {"proc": None, "argv": None}


def preview_running():
    p = _preview["proc"]
    return p is not None and p.poll() is None


def stop_preview():
    p = _preview["proc"]
    if p is not None and p.poll() is None:
        p.terminate()
        try:
            p.wait(timeout=5)
        except subprocess.TimeoutExpired:
            p.kill()
    _preview["proc"] = None


def launch(argv):
    stop_preview()
    _preview["argv"] = argv
    log = tempfile.TemporaryFile(mode="w+", errors="replace")  # never a pipe nobody drains
    _preview["proc"] = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=log)
    _preview["log"] = log
    return _preview["proc"]


def preview_errors():
    log = _preview.get("log")
    if log is None:
        return []
    log.seek(0)
    return [line.strip() for line in log.read().splitlines() if line.strip()]


def restart_preview():
    if _preview["argv"]:
        launch(_preview["argv"])


class LFD_OT_preview(bpy.types.Operator, pipeline.JobOperator):
    """Play the baked scene with lfd-play in a window, or fullscreen on the display (bakes first if needed)"""

    bl_idname = "lfd.preview"
    bl_label = "Preview"
    bl_options = {"REGISTER"}

    screenshot: bpy.props.StringProperty(
        name="Screenshot", default="", options={"SKIP_SAVE"},
        description="Scripts/tests: render N frames, save the window to this PNG and wait for lfd-play to exit")
    frames: bpy.props.IntProperty(name="Frames", default=1, min=1, options={"SKIP_SAVE"})

    def execute(self, context):
        self.init_job_state()
        try:
            r = pipeline.Resolved(context, need=("lfd-bake", "lfd-play"))
            pipeline.export_scene(context, r, self)
        except (pipeline.SetupError, RuntimeError) as e:
            return self.fail(context, str(e))
        self.resolved = r
        steps = [] if pipeline.pack_is_current(r) else [pipeline.bake_step(r, self)]
        return self.start_job(context, jobs.Job(steps))

    def on_finished(self, context):
        r, s = self.resolved, context.scene.lfd
        # The preview's animation starts at Blender's current frame (lfd-play's frame k is
        # at k / fps, the glTF time of Blender frame k).
        argv = [r.tools["lfd-play"], r.pack, *r.display_args(), "--renderer", s.renderer,
                "--fps", f"{context.scene.render.fps:g}", "--first-frame", str(max(context.scene.frame_current, 0))]
        if s.fullscreen:
            argv.append("--fullscreen")
            if s.monitor:
                argv += ["--monitor", s.monitor]
        if self.screenshot:
            argv += ["--frames", str(self.frames), "--screenshot", bpy.path.abspath(self.screenshot)]
        try:
            proc = launch(argv)
        except OSError as e:
            return self.fail(context, f"cannot run lfd-play: {e.strerror}")
        # A refused start (no display, monitor mismatch, bad profile) ends at once: say why.
        deadline = time.time() + (300 if self.screenshot else 1.0)
        while proc.poll() is None and time.time() < deadline:
            time.sleep(0.05)
        if proc.poll() not in (None, 0):
            err = preview_errors()
            return self.fail(context, (err[-1] if err else f"lfd-play exited with status {proc.returncode}"))
        text = f"Previewing {r.pack}" + (" fullscreen" if s.fullscreen else "")
        self.report({"INFO"}, text)
        s.last_message = text
        return {"FINISHED"}


class LFD_OT_stop_preview(bpy.types.Operator):
    """Close the lfd-play preview"""

    bl_idname = "lfd.stop_preview"
    bl_label = "Stop preview"

    def execute(self, context):
        stop_preview()
        return {"FINISHED"}


classes = (LFD_OT_preview, LFD_OT_stop_preview)
