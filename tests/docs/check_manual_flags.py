#!/usr/bin/env python3
"""Every flag a tool's --help prints is in its manual's "Flags" table, and the table lists no
flag the tool does not have (issue 39: README -> tool manual -> flag, two clicks).

    check_manual_flags.py SOURCE_DIR TOOL=EXECUTABLE=MANUAL [...]

e.g. lfd-bake=build/baker/lfd-bake=docs/baker/lfd-bake.md. The table is the "## Flags"
section of MANUAL (relative to SOURCE_DIR): one row per option, its names in backticks in the
first column. -h/--help is left out.
"""
import os
import re
import subprocess
import sys

# An option line of the help: CLI11's "  -o,--output TEXT   ..." or a hand-written
# "  --scene         ..." (lfd-make-samples).
OPTION = re.compile(r"^  (-{1,2}[A-Za-z][\w-]*(?:,-{1,2}[A-Za-z][\w-]*)*)(?:\{[^}]*\})?(?:\s+(.*))?$")


def help_flags(command):
    """[(names, help line)] for every option the command's help prints, in its order."""
    run = subprocess.run(command, capture_output=True, text=True, timeout=60)
    text = run.stdout + run.stderr
    out = []
    lines = text.split("\n")
    cli11 = "Options:" in lines
    for i, ln in enumerate(lines):
        m = OPTION.match(ln)
        if not m:
            continue
        names = [n for n in m.group(1).split(",") if n.startswith("--")]
        if not names or names == ["--help"]:
            continue
        if cli11:
            # CLI11: names and type (TEXT, UINT=2, FLOAT:FLOAT in [..]) in the first 30
            # columns, the description from column 30 (or on the next line when they are longer).
            desc = ln[30:].strip() if len(ln) > 30 and ln[29] == " " else ""
        else:
            parts = re.split(r"\s{2,}", (m.group(2) or "").strip(), maxsplit=1)
            desc = parts[-1]
        j = i + 1
        while j < len(lines) and re.match(r"^\s{8,}\S", lines[j]) and not OPTION.match(lines[j]):
            desc = (desc + " " + lines[j].strip()).strip()
            j += 1
        out.append((names, desc))
    if not out:
        raise SystemExit(f"no options found in the help of {' '.join(command)} (exit {run.returncode})")
    return out


def table_flags(manual):
    text = open(manual, encoding="utf-8").read().split("\n")
    try:
        start = text.index("## Flags")
    except ValueError:
        return None
    flags = set()
    for ln in text[start + 1:]:
        if ln.startswith("#"):
            break
        if ln.startswith("| `"):
            first = ln.split("|")[1]
            flags.update(re.findall(r"`(--[\w-]+)`", first))
    return flags


def main():
    root = sys.argv[1]
    problems = []
    for spec in sys.argv[2:]:
        tool, exe, manual = spec.split("=", 2)
        listed = table_flags(os.path.join(root, manual))
        if listed is None:
            problems.append(f"{manual}: no '## Flags' section (the table of {tool}'s flags)")
            continue
        printed = set()
        for names, _ in help_flags([exe, "--help"]):
            printed.update(names)
            missing = [n for n in names if n not in listed]
            if missing:
                problems.append(f"{manual}: {tool} --help prints {', '.join(missing)}, the Flags table does not")
        for extra in sorted(listed - printed):
            problems.append(f"{manual}: the Flags table lists {extra}, {tool} --help does not print it")
        print(f"{tool}: {len(printed)} flags, all in {manual}" if not any(manual in p for p in problems)
              else f"{tool}: see below")
    for p in problems:
        print("FAIL:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
