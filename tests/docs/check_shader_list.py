#!/usr/bin/env python3
"""Every shader file under shaders/ (.glsl, .vert, .geom, .frag, .comp) is listed in
cmake/shader_list.cmake, and every listed file exists. The player embeds the listed files
(cmake/embed_shaders.cmake); a shader added without a line there would be missing from the
binary and fail only when a program first asks for it, so this check names it instead.

Usage: check_shader_list.py REPO_ROOT
"""
import os
import re
import sys

EXTENSIONS = (".glsl", ".vert", ".geom", ".frag", ".comp")


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
    shaders = os.path.join(root, "shaders")
    with open(os.path.join(root, "cmake", "shader_list.cmake"), encoding="utf-8") as f:
        text = re.sub(r"#[^\n]*", "", f.read())
    block = re.search(r"set\(LFD_SHADERS([^)]*)\)", text)
    listed = set(block.group(1).split()) if block else set()
    present = {n for n in os.listdir(shaders) if n.endswith(EXTENSIONS)}
    problems = [f"NOT LISTED: shaders/{n} is not in cmake/shader_list.cmake" for n in sorted(present - listed)]
    problems += [f"MISSING: shaders/{n} is listed in cmake/shader_list.cmake but does not exist"
                 for n in sorted(listed - present)]
    for p in problems:
        print(p)
    if not listed:
        print("cmake/shader_list.cmake: no set(LFD_SHADERS ...) block")
        return 1
    print(f"{len(listed)} shaders listed, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
