#!/usr/bin/env python3
"""Checks that every glTF issue code (baker/gltf/gltf_issue_codes.h) is asserted by some test:
`IssueCode::NAME` appears in a test source under tests/, except the codes listed in EXEMPT
with the reason no small test input makes them.

Usage: check_issue_codes_tested.py SOURCE_DIR
"""
import pathlib
import re
import sys

EXEMPT = {
    "TINYGLTF_WARNING": "tinygltf's own warnings, passed on: what makes tinygltf warn is tinygltf's",
    "DRACO_ACCESSOR_SHARED": "needs a file whose two Draco streams fill one accessor (no such fixture)",
    "ACCESSOR_READ_FAILED": "an accessor that fits its view reads; the checks report what else fails first",
}


def main():
    root = pathlib.Path(sys.argv[1])
    header = (root / "baker" / "gltf" / "gltf_issue_codes.h").read_text()
    codes = re.findall(r"^\s*X\((\w+),", header, re.M)
    if not codes:
        sys.exit("no codes found in baker/gltf/gltf_issue_codes.h")
    sources = "\n".join(p.read_text() for p in (root / "tests").rglob("*") if p.suffix in (".cpp", ".h"))
    untested = [c for c in codes if c not in EXEMPT and not re.search(r"IssueCode::" + c + r"\b", sources)]
    stale = [c for c in EXEMPT if c not in codes]
    for c in untested:
        print(f"{c}: no test asserts it (IssueCode::{c} in tests/)")
    for c in stale:
        print(f"{c}: exempt here but not in the catalogue")
    if untested or stale:
        sys.exit(1)
    print(f"{len(codes) - len(EXEMPT)} of {len(codes)} codes asserted by tests; exempt: {', '.join(EXEMPT)}")


if __name__ == "__main__":
    main()
