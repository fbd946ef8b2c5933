# SPDX-License-Identifier: MIT
"""Finding lfd-bake / lfd-play, checking they are new enough, and the display profiles
they ship. No bpy here: the functions take plain values, so tests can call them."""

import json
import os
import shutil
import subprocess

# Flags the add-on passes; a tool whose --help lacks one is too old (neither tool has a
# --version flag; the pack records the baker's version, the binaries do not print it).
REQUIRED_FLAGS = {
    "lfd-bake": ("--display", "--max-edge-px", "--simplify", "--texture-compression", "--threads", "--inspect"),
    "lfd-play": ("--headless", "--display", "--quilt", "--out", "--frames", "--frame", "--fps",
                 "--no-turntable", "--fullscreen", "--monitor", "--renderer"),
}

_help_cache = {}  # (path, mtime) -> help text


class ToolError(Exception):
    """A tool is missing or unusable; the message is one line for a Blender report."""


def search_dirs(tools_dir):
    """The folders named in tools_dir (several separated by os.pathsep), absolute."""
    return [os.path.abspath(os.path.expanduser(d)) for d in (tools_dir or "").split(os.pathsep) if d.strip()]


def find_tool(name, tools_dir):
    """Path of the tool: in tools_dir's folders when set, else on PATH. None if absent."""
    dirs = search_dirs(tools_dir)
    if dirs:
        for d in dirs:
            candidate = os.path.join(d, name)
            if os.path.isfile(candidate) and os.access(candidate, os.X_OK):
                return candidate
        return None
    return shutil.which(name)


def tool_help(path):
    try:
        key = (path, os.stat(path).st_mtime_ns)
    except OSError as e:
        raise ToolError(f"{path}: {e.strerror}")
    if key not in _help_cache:
        try:
            run = subprocess.run([path, "--help"], stdin=subprocess.DEVNULL, capture_output=True, text=True,
                                 timeout=20)
        except (OSError, subprocess.TimeoutExpired) as e:
            raise ToolError(f"{path} does not run: {e}")
        _help_cache[key] = run.stdout + run.stderr
    return _help_cache[key]


def locate(names, tools_dir):
    """{name: path} for every tool in names, or ToolError naming what is missing or too old."""
    found = {}
    for name in names:
        path = find_tool(name, tools_dir)
        if path is None:
            where = ("in " + os.pathsep.join(search_dirs(tools_dir))) if search_dirs(tools_dir) else "on PATH"
            raise ToolError(f"{name} not found {where}: build the toolkit (scripts/build.sh) or install it "
                            "(cmake --install), then set Tools folder in Scene > Light Field Display")
        text = tool_help(path)
        missing = [f for f in REQUIRED_FLAGS.get(name, ()) if f not in text]
        if missing:
            raise ToolError(f"{path} is too old for this add-on (no {', '.join(missing)}): rebuild or reinstall "
                            "the toolkit")
        found[name] = path
    return found


def tools_status(tools_dir):
    """One line for the panel: where the tools are, or what is wrong."""
    try:
        found = locate(("lfd-bake", "lfd-play"), tools_dir)
    except ToolError as e:
        return False, str(e)
    return True, "  ".join(f"{n}: {p}" for n, p in found.items())


def profile_dirs(tool_paths, addon_dir):
    """Where shipped display profiles live: PREFIX/share/lfd/profiles beside installed tools,
    samples/profiles of the source tree above a build tree or above the add-on's folder."""
    dirs = []
    starts = [os.path.dirname(p) for p in tool_paths if p] + [addon_dir]
    for start in starts:
        d = os.path.abspath(start)
        for _ in range(5):
            for candidate in (os.path.join(d, "share", "lfd", "profiles"), os.path.join(d, "samples", "profiles")):
                if os.path.isdir(candidate) and candidate not in dirs:
                    dirs.append(candidate)
            cache = os.path.join(d, "CMakeCache.txt")  # a build tree: its source tree's profiles
            if os.path.isfile(cache):
                with open(cache, encoding="utf-8", errors="replace") as f:
                    for line in f:
                        if line.startswith("CMAKE_HOME_DIRECTORY:"):
                            src = os.path.join(line.split("=", 1)[1].strip(), "samples", "profiles")
                            if os.path.isdir(src) and src not in dirs:
                                dirs.append(src)
            d = os.path.dirname(d)
    return dirs


def shipped_profiles(tool_paths, addon_dir):
    """[(path, label)] of the *.json profiles found, each file name once."""
    seen, out = set(), []
    for d in profile_dirs(tool_paths, addon_dir):
        for name in sorted(os.listdir(d)):
            if name.endswith(".json") and name not in seen:
                seen.add(name)
                out.append((os.path.join(d, name), name[:-5]))
    return out


def check_profile(path):
    """Raises ToolError unless path is a readable JSON file ('' = the built-in prototype).
    The tools validate the profile's content themselves (their error becomes the report)."""
    if not path:
        return
    try:
        with open(path, "rb") as f:
            json.loads(f.read().decode("utf-8"))
    except OSError as e:
        raise ToolError(f"display profile {path}: {e.strerror}")
    except (UnicodeDecodeError, ValueError) as e:
        raise ToolError(f"display profile {path}: not a JSON file ({e})")
