# SPDX-License-Identifier: MIT
"""What Bake, Preview and Render share: the settings resolved to absolute paths, the
export, the lfd-bake step, and a mixin that runs a Job modally (UI: progress in the status
bar, Esc cancels) or to the end (background mode)."""

import hashlib
import json
import os
import tempfile
import time

import bpy

from . import export, jobs, reports, tools

SIDECAR = ".blender-source.json"  # beside the pack: what it was baked from


class SetupError(Exception):
    """A bad setting; the message is one line for a Blender report."""


def abspath(path, fallback_dir):
    if path.startswith("//") and not bpy.data.filepath:
        return os.path.join(fallback_dir, path[2:])
    return os.path.abspath(bpy.path.abspath(path))


class Resolved:
    """Scene.lfd with absolute paths, the tools located and the profile checked."""

    def __init__(self, context, need=("lfd-bake",)):
        t0 = time.perf_counter()
        scene = context.scene
        s = scene.lfd
        self.scene, self.settings = scene, s
        try:
            self.tools = tools.locate(need, bpy.path.abspath(s.tools_dir) if s.tools_dir else "")
            self.profile = abspath(s.display_profile, "") if s.display_profile else ""
            tools.check_profile(self.profile)
        except tools.ToolError as e:
            raise SetupError(str(e))
        tmp = os.path.join(tempfile.gettempdir(), "lfd_blender")
        self.output_dir = abspath(s.output_dir or "//lfd/", tmp)
        try:
            os.makedirs(self.output_dir, exist_ok=True)
        except OSError as e:
            raise SetupError(f"output folder {self.output_dir}: {e.strerror}")
        self.name = bpy.path.clean_name(scene.name) or "scene"
        self.glb = os.path.join(self.output_dir, self.name + ".glb")
        self.pack = os.path.join(self.output_dir, self.name + ".lfdpack")
        self.check_seconds = time.perf_counter() - t0

    def bake_argv(self):
        s = self.settings
        argv = [self.tools["lfd-bake"], self.glb, "-o", self.pack, "--max-edge-px", f"{s.max_edge_px:g}",
                "--simplify", f"{s.simplify:g}", "--texture-compression", s.texture_compression]
        if self.profile:
            argv += ["--display", self.profile]
        if s.threads:
            argv += ["--threads", str(s.threads)]
        return argv

    def display_args(self):
        return ["--display", self.profile] if self.profile else []


def _sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def _source_record(r):
    return {"glb_sha256": _sha256(r.glb), "argv": r.bake_argv()[1:],
            "profile_sha256": _sha256(r.profile) if r.profile else ""}


def pack_is_current(r):
    """True when the pack was baked from the file just exported with the same options."""
    try:
        with open(r.pack + SIDECAR, encoding="utf-8") as f:
            return os.path.isfile(r.pack) and json.load(f) == _source_record(r)
    except (OSError, ValueError):
        return False


class Timings:
    def __init__(self):
        self.check = 0.0   # locating the tools, checking them and the profile
        self.export = 0.0
        self.launch = 0.0  # Popen of lfd-bake
        self.bake = 0.0    # lfd-bake's own run, from launch to exit


def bake_step(r, op):
    """The lfd-bake step: warnings and errors become reports, progress the bar."""
    names = reports.GltfNames(reports.read_gltf_json(r.glb))
    state = {"fraction": 0.0, "error": None, "t0": None}

    def on_line(line, from_stderr):
        if state["t0"] is None:
            state["t0"] = time.perf_counter()
        if not from_stderr:
            p = reports.bake_progress(line)
            if p:
                state["fraction"], op.status = p
                if bpy.app.background:
                    print("lfd-bake:", line, flush=True)
            return
        level, text = reports.classify(line, from_stderr)
        text = names.translate(reports.strip_file(text, r.glb))
        if level == "ERROR" and state["error"] is None:
            state["error"] = text
            return  # the step's failure reports it
        op.messages.append((level, text))

    def on_exit(code):
        op.timings.bake = time.perf_counter() - step.t_launched
        if code != 0:
            raise jobs.StepFailed("lfd-bake: " + (state["error"] or f"failed (exit status {code})"))
        with open(r.pack + SIDECAR, "w", encoding="utf-8") as f:
            json.dump(_source_record(r), f)
        r.settings.last_pack = r.pack

    step = jobs.ProcessStep("Baking", r.bake_argv(), on_line, on_exit, lambda: state["fraction"], weight=1.0)
    return step


def export_scene(context, r, op):
    seconds = export.export_glb(context, r.glb, r.settings.export_scope)
    op.timings.export = seconds
    if reports.read_gltf_json(r.glb) is None:
        raise SetupError(f"the glTF exporter wrote no readable file at {r.glb}")
    return seconds


_active = {"op": None}  # one job at a time


class JobOperator:
    """Mixin for operators that run a jobs.Job."""

    def init_job_state(self):
        self.messages = []
        self.status = ""
        self.timings = Timings()
        self.job = None
        self._timer = None
        self.t_start = time.perf_counter()

    def fail(self, context, text):
        self.report({"ERROR"}, text)
        if context and getattr(context, "scene", None) and hasattr(context.scene, "lfd"):
            context.scene.lfd.last_message = text
        return {"CANCELLED"}

    def flush(self):
        for level, text in self.messages:
            self.report({level}, text)
        self.messages.clear()

    def start_job(self, context, job):
        if _active["op"] is not None and not bpy.app.background:
            return self.fail(context, "another LFD bake or render is still running (Esc cancels it)")
        self.job = job
        if bpy.app.background:
            job.run_blocking()
            return self.finish(context)
        _active["op"] = self
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.1, window=context.window)
        wm.progress_begin(0, 1000)
        wm.modal_handler_add(self)
        return {"RUNNING_MODAL"}

    def modal(self, context, event):
        if event.type == "ESC" and event.value == "PRESS":
            self.job.cancel()
        elif event.type != "TIMER":
            return {"PASS_THROUGH"}
        state = self.job.poll()
        self.flush()
        wm = context.window_manager
        wm.progress_update(int(1000 * self.job.fraction()))
        if context.workspace:
            context.workspace.status_text_set(
                f"LFD {self.job.label()}: {100 * self.job.fraction():.0f}%  {self.status}   (Esc cancels)")
        if state == "RUNNING":
            return {"RUNNING_MODAL"}
        wm.event_timer_remove(self._timer)
        wm.progress_end()
        if context.workspace:
            context.workspace.status_text_set(None)
        _active["op"] = None
        return self.finish(context)

    def finish(self, context):
        self.flush()
        state = self.job.state
        if state == "FINISHED":
            return self.on_finished(context)
        if state == "CANCELLED":
            self.report({"WARNING"}, "cancelled")
            context.scene.lfd.last_message = "cancelled"
            return {"CANCELLED"}
        return self.fail(context, self.job.error or "failed")

    def on_finished(self, context):
        return {"FINISHED"}
