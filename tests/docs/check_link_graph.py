#!/usr/bin/env python3
"""Checks that ARCHITECTURE.md's link graph is the one CMake builds.

ARCHITECTURE.md holds the graph between the lines `<!-- link-graph -->` and
`<!-- /link-graph -->`, one target a line: `target: dep dep ...`, listing the project's own
targets it links (any visibility). This script reads every target_link_libraries() of the
project's CMakeLists.txt files (tests/ excepted: test binaries link what they test) and
fails, naming each difference, when the two disagree.

Usage: check_link_graph.py SOURCE_DIR
"""
import pathlib
import re
import sys

SKIPPED_DIRS = {"build", "tests", ".git"}
KEYWORDS = {"PUBLIC", "PRIVATE", "INTERFACE"}


def cmake_files(root):
    for path in sorted(root.rglob("CMakeLists.txt")):
        rel = path.relative_to(root)
        if rel.parts[0] in SKIPPED_DIRS or rel.parts[0].startswith("build"):
            continue
        yield path


def commands(text, name):
    """The argument lists of every `name(...)` call (comments stripped, no nested parens)."""
    text = re.sub(r"#[^\n]*", "", text)
    for match in re.finditer(r"\b" + name + r"\s*\(([^)]*)\)", text):
        yield match.group(1).split()


def cmake_graph(root):
    texts = [p.read_text() for p in cmake_files(root)]
    targets = set()
    for text in texts:
        for kind in ("add_library", "add_executable"):
            for args in commands(text, kind):
                if args and "${" not in args[0] and "IMPORTED" not in args and "ALIAS" not in args:
                    targets.add(args[0])
    graph = {t: set() for t in targets}
    for text in texts:
        for args in commands(text, "target_link_libraries"):
            if args and args[0] in graph:
                graph[args[0]].update(a for a in args[1:] if a in targets and a not in KEYWORDS)
    return graph


def documented_graph(architecture):
    text = architecture.read_text()
    block = re.search(r"<!-- link-graph -->(.*?)<!-- /link-graph -->", text, re.S)
    if not block:
        sys.exit(f"{architecture}: no <!-- link-graph --> ... <!-- /link-graph --> block")
    graph = {}
    for line in block.group(1).splitlines():
        line = line.strip().strip("`")
        if not line or ":" not in line:
            continue
        target, deps = line.split(":", 1)
        graph[target.strip()] = set(deps.split())
    return graph


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    built = cmake_graph(root)
    documented = documented_graph(root / "ARCHITECTURE.md")
    problems = []
    for target in sorted(built.keys() | documented.keys()):
        if target not in documented:
            problems.append(f"{target}: built by CMake, missing from ARCHITECTURE.md")
        elif target not in built:
            problems.append(f"{target}: in ARCHITECTURE.md, but no CMakeLists.txt builds it")
        elif built[target] != documented[target]:
            extra = sorted(documented[target] - built[target])
            missing = sorted(built[target] - documented[target])
            problems.append(f"{target}: ARCHITECTURE.md lists {extra} that CMake does not link, "
                            f"and misses {missing} that it does")
    for problem in problems:
        print(problem)
    print(f"{len(built)} targets compared, {len(problems)} differences")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
