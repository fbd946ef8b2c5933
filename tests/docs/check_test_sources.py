#!/usr/bin/env python3
"""Every C++ file under tests/ (tests/fuzz/ has its own CMakeLists.txt) is listed in
tests/CMakeLists.txt. Test binaries list their sources instead of globbing them (issue 39),
so a test file added without a line there would compile into nothing and its tests would
silently never run; this check fails instead, naming the file.

Usage: check_test_sources.py REPO_ROOT
"""
import os
import re
import sys


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
    tests = os.path.join(root, "tests")
    with open(os.path.join(tests, "CMakeLists.txt"), encoding="utf-8") as f:
        listed = set(re.findall(r"[\w./-]+\.cpp", f.read()))
    missing = []
    for folder, dirs, files in os.walk(tests):
        rel = os.path.relpath(folder, tests)
        if rel == "fuzz" or rel.startswith("fuzz" + os.sep) or rel.startswith("data"):
            continue
        for name in files:
            if name.endswith(".cpp"):
                path = os.path.normpath(os.path.join(rel, name)).replace(os.sep, "/")
                if path not in listed:
                    missing.append(path)
    for path in sorted(missing):
        print(f"NOT LISTED: tests/{path} is in no test binary's SOURCES in tests/CMakeLists.txt")
    print(f"checked {len(listed)} listed sources; {len(missing)} test file(s) not listed")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
