# SPDX-License-Identifier: MIT
"""Background work as a list of steps: child processes (argument vectors, no shell) read
line by line on reader threads, and Python steps run on Blender's main thread. The UI
polls a Job from a modal operator's timer; background mode (blender -b) runs it to the end
(Job.run_blocking) so scripts and tests get the result when the operator returns."""

import os
import queue
import signal
import subprocess
import threading
import time


class StepFailed(Exception):
    """A step failed; the message is one line for a Blender report."""


class ProcessStep:
    """Runs argv. on_line(text, from_stderr) sees every output line; on_exit(returncode)
    raises StepFailed or returns; progress() -> fraction of this step, or None."""

    def __init__(self, label, argv, on_line=None, on_exit=None, progress=None, weight=1.0):
        self.label, self.argv, self.weight = label, argv, weight
        self.on_line, self.on_exit, self.progress = on_line, on_exit, progress
        self.proc = None
        self.lines = queue.Queue()
        self.readers = []
        self.launch_seconds = 0.0

    def start(self):
        if callable(self.argv):  # built when reached (it may name files earlier steps wrote)
            self.argv = self.argv()
        t0 = time.perf_counter()
        try:
            self.proc = subprocess.Popen(self.argv, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                         stderr=subprocess.PIPE, text=True, errors="replace",
                                         start_new_session=True)
        except OSError as e:
            raise StepFailed(f"{self.label}: cannot run {self.argv[0]}: {e.strerror}")
        self.t_launched = time.perf_counter()
        self.launch_seconds = self.t_launched - t0
        for stream, is_err in ((self.proc.stdout, False), (self.proc.stderr, True)):
            t = threading.Thread(target=self._read, args=(stream, is_err), daemon=True)
            t.start()
            self.readers.append(t)

    def _read(self, stream, is_err):
        for line in stream:
            self.lines.put((line.rstrip("\n"), is_err))
        stream.close()

    def _drain(self):
        while True:
            try:
                text, is_err = self.lines.get_nowait()
            except queue.Empty:
                return
            if self.on_line and text.strip():
                self.on_line(text, is_err)

    def poll(self):
        """True when finished (raises StepFailed on failure)."""
        self._drain()
        if self.proc.poll() is None:
            return False
        for t in self.readers:
            t.join()
        self._drain()
        if self.on_exit:
            self.on_exit(self.proc.returncode)
        elif self.proc.returncode != 0:
            raise StepFailed(f"{self.label} failed (exit status {self.proc.returncode})")
        return True

    def cancel(self):
        if self.proc and self.proc.poll() is None:
            try:
                os.killpg(self.proc.pid, signal.SIGTERM)
            except OSError:
                pass
            try:
                self.proc.wait(timeout=5)
            except subprocess.TimeoutExpired:
                os.killpg(self.proc.pid, signal.SIGKILL)
                self.proc.wait()


class FuncStep:
    """Runs fn() on the main thread when reached."""

    def __init__(self, label, fn, weight=0.05):
        self.label, self.fn, self.weight = label, fn, weight
        self.progress = None
        self.launch_seconds = 0.0

    def start(self):
        pass

    def poll(self):
        self.fn()
        return True

    def cancel(self):
        pass


class Job:
    def __init__(self, steps, on_cleanup=None):
        self.steps = list(steps)
        self.index = -1
        self.state = "PENDING"  # RUNNING, FINISHED, FAILED, CANCELLED
        self.error = None
        self.on_cleanup = on_cleanup
        self.launch_seconds = 0.0

    def add(self, step):
        self.steps.append(step)

    def _next(self):
        self.index += 1
        if self.index >= len(self.steps):
            self._end("FINISHED")
            return
        step = self.steps[self.index]
        step.start()
        self.launch_seconds += step.launch_seconds

    def _end(self, state, error=None):
        self.state, self.error = state, error
        if self.on_cleanup:
            self.on_cleanup(state)

    def poll(self):
        """Advances the job; returns its state."""
        try:
            if self.state == "PENDING":
                self.state = "RUNNING"
                self._next()
            while self.state == "RUNNING" and self.steps[self.index].poll():
                self._next()
        except StepFailed as e:
            self._end("FAILED", str(e))
        return self.state

    def cancel(self):
        if self.state in ("PENDING", "RUNNING"):
            if 0 <= self.index < len(self.steps):
                self.steps[self.index].cancel()
            self._end("CANCELLED", "cancelled")

    def fraction(self):
        total = sum(s.weight for s in self.steps) or 1.0
        done = sum(s.weight for s in self.steps[:max(self.index, 0)])
        if 0 <= self.index < len(self.steps):
            step = self.steps[self.index]
            p = step.progress() if step.progress else None
            if p is not None:
                done += step.weight * max(0.0, min(1.0, p))
        return done / total

    def label(self):
        return self.steps[self.index].label if 0 <= self.index < len(self.steps) else ""

    def run_blocking(self, interval=0.02):
        while self.poll() == "RUNNING":
            time.sleep(interval)
        return self.state
