# SPDX-License-Identifier: MIT
"""LFD_OT_bake: export the scene with Blender's glTF exporter and bake it with lfd-bake."""

import os
import time

import bpy

from . import jobs, pipeline, preview_operator


class LFD_OT_bake(bpy.types.Operator, pipeline.JobOperator):
    """Export the scene as glTF and bake it into a .lfdpack for the chosen display"""

    bl_idname = "lfd.bake"
    bl_label = "Bake"
    bl_options = {"REGISTER"}

    def execute(self, context):
        self.init_job_state()
        try:
            r = pipeline.Resolved(context, need=("lfd-bake",))
            pipeline.export_scene(context, r, self)
        except (pipeline.SetupError, RuntimeError) as e:
            return self.fail(context, str(e))
        self.resolved = r
        step = pipeline.bake_step(r, self)
        job = jobs.Job([step])
        self.bake_step = step
        return self.start_job(context, job)

    def on_finished(self, context):
        r = self.resolved
        t = self.timings
        t.launch = self.job.launch_seconds
        t.check = r.check_seconds
        size = os.path.getsize(r.pack)
        total = time.perf_counter() - self.t_start
        text = (f"Baked {r.pack} ({size / 1e6:.2f} MB) in {total:.2f} s: export {t.export:.3f} s, "
                f"launch {t.launch * 1000:.1f} ms, lfd-bake {t.bake:.2f} s, tool check {t.check:.3f} s")
        self.report({"INFO"}, text)
        context.scene.lfd.last_message = text
        if preview_operator.preview_running():
            preview_operator.restart_preview()
            self.report({"INFO"}, "Preview reloaded")
        return {"FINISHED"}


classes = (LFD_OT_bake,)
