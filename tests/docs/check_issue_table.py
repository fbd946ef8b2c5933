#!/usr/bin/env python3
"""Checks that docs/baker/gltf-issues.md holds the issue-code table `lfd-bake
--list-issue-codes` prints (between `<!-- issue-codes -->` and `<!-- /issue-codes -->`).

Usage: check_issue_table.py LFD_BAKE SOURCE_DIR
"""
import pathlib
import re
import subprocess
import sys


def main():
    bake, root = sys.argv[1], pathlib.Path(sys.argv[2])
    doc = root / "docs" / "baker" / "gltf-issues.md"
    generated = subprocess.run([bake, "--list-issue-codes"], check=True, capture_output=True, text=True).stdout
    block = re.search(r"<!-- issue-codes -->\n(.*?)<!-- /issue-codes -->", doc.read_text(), re.S)
    if not block:
        sys.exit(f"{doc}: no <!-- issue-codes --> ... <!-- /issue-codes --> block")
    if block.group(1) != generated:
        sys.exit(f"{doc}: the issue-code table differs from `lfd-bake --list-issue-codes`; regenerate it: "
                 f"replace the table between the markers with the output of `{bake} --list-issue-codes`")
    print(f"{doc}: the table matches ({generated.count(chr(10)) - 2} codes)")


if __name__ == "__main__":
    main()
