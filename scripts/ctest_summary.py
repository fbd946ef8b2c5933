#!/usr/bin/env python3
"""Prints how many tests ran per test binary, from a CTest JUnit file (ctest --output-junit).

    ctest_summary.py JUNIT.xml TESTS_DIR

TESTS_DIR holds the GoogleTest binaries (build/tests); each binary's --gtest_list_tests
maps test names to it. Every skipped test is listed with GoogleTest's reason, so a run
never hides what did not run. Exit status 0 (the CTest run itself decides pass/fail).
"""
import collections
import glob
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET


def tests_of(binary):
    out = subprocess.run([binary, "--gtest_list_tests"], capture_output=True, text=True).stdout
    names, suite = [], ""
    for line in out.splitlines():
        if not line.startswith(" "):
            suite = line.split("#")[0].strip()
        else:
            names.append(suite + line.split("#")[0].strip())
    return names


def skip_reason(output):
    lines = (output or "").splitlines()
    for i, line in enumerate(lines):
        if re.search(r": Skipped$", line):
            return (lines[i + 1] if i + 1 < len(lines) else "").strip() or "(no reason given)"
    return "(no reason given)"


def main():
    junit, tests_dir = sys.argv[1], sys.argv[2]
    owner = {}
    for binary in sorted(glob.glob(os.path.join(tests_dir, "lfd_*_tests"))):
        for name in tests_of(binary):
            owner[name] = os.path.basename(binary)
    counts = collections.defaultdict(collections.Counter)
    skipped = []
    for case in ET.parse(junit).getroot().iter("testcase"):
        name, status = case.get("name"), case.get("status")
        suite = owner.get(name, "other")
        if case.find("failure") is not None or status == "fail":
            counts[suite]["failed"] += 1
        elif status == "run":
            counts[suite]["passed"] += 1
        else:  # skipped (GTEST_SKIP), disabled, notrun
            counts[suite]["skipped"] += 1
            out = case.find("system-out")
            skipped.append((suite, name, skip_reason(out.text if out is not None else "")))
    for suite in sorted(counts):
        c = counts[suite]
        print("tests: %-18s %4d ran (%d passed, %d failed), %d skipped"
              % (suite, c["passed"] + c["failed"], c["passed"], c["failed"], c["skipped"]))
    for suite, name, reason in skipped:
        print("tests: skipped %s %s: %s" % (suite, name, reason))


if __name__ == "__main__":
    main()
