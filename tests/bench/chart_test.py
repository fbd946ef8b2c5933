#!/usr/bin/env python3
"""Test for player/bench/bench_chart.py (lfd-bench's matrix chart).

    /usr/bin/python3 tests/bench/chart_test.py [path/to/bench_chart.py]

Builds a synthetic results.csv with near-equal errors (3.44400 and 3.44414 RMSE) over a
narrow time range (one panel, linear time axis) and a wide one (another panel, log time
axis), runs bench_chart.py on it into a temporary directory and checks that chart.png and
chart.svg exist and that every tick label in the SVG is a plain number: no offset text
("+3.444"), no scientific notation ("1e3", "x10^2"), and that the error axis starts at 0
so near-equal errors are drawn near-equal. Exits 0 on success, 1 on failure, 77 (skip)
where no python3 with matplotlib is found.
"""
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = sys.argv[1] if len(sys.argv) > 1 else os.path.normpath(
    os.path.join(HERE, "..", "..", "player", "bench", "bench_chart.py"))

HEADER = ["scene", "triangles", "drawn_triangles", "views", "view_width", "view_height", "config", "renderer",
          "aa", "ss", "timed", "frames", "total_ms", "eia_rmse", "pareto", "reference"]
ROWS = [
    # Narrow: times within 1.1x, errors equal to the fourth decimal.
    ("narrow", "mvr", "mvr", "none", "1", "1", "100.0", "3.44414", "1"),
    ("narrow", "lfdpr", "lfdpr", "none", "1", "1", "101.0", "3.44400", "1"),
    ("narrow", "mvr-layered", "mvr-layered", "none", "1", "1", "100.5", "3.44414", "0"),
    ("narrow", "gstd", "gstd", "none", "1", "0", "", "0", "0"),
    # Wide: times over 50x (log axis), with supersampling and reconstruction variants.
    ("wide", "mvr", "mvr", "none", "1", "1", "52.0", "3.44414", "0"),
    ("wide", "lfdpr", "lfdpr", "none", "1", "1", "50.0", "3.44400", "1"),
    ("wide", "lfdpr+ss-2s", "lfdpr", "none", "2s", "1", "410.0", "2.00000", "1"),
    ("wide", "mvr+ss-2s", "mvr", "none", "2s", "1", "1200.0", "2.00010", "0"),
    ("wide", "lfdpr+aa-view-spatial+ss-2v", "lfdpr", "view-spatial", "2v", "1", "2600.0", "3.10000", "0"),
]


def find_python():
    for exe in ("/usr/bin/python3", sys.executable):
        if exe and os.path.exists(exe):
            if subprocess.run([exe, "-c", "import matplotlib"], capture_output=True).returncode == 0:
                return exe
    return None


def tick_labels(svg, axis):
    """Texts of the `axis` (x or y) tick labels: matplotlib writes each label's text as a
    comment `<!-- TEXT -->` inside the tick's group `<g id="xtick_N">` (minor ticks too)."""
    parser = ET.XMLParser(target=ET.TreeBuilder(insert_comments=True))
    root = ET.fromstring(svg, parser=parser)
    labels = []
    for g in root.iter("{http://www.w3.org/2000/svg}g"):
        if re.match(r"^%stick_\d+$" % axis, g.get("id", "")):
            labels += [c.text.strip() for c in g.iter() if c.tag is ET.Comment and c.text]
    return labels


def main():
    py = find_python()
    if py is None:
        print("chart_test: SKIP: no python3 with matplotlib")
        return 77
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        csv_path = os.path.join(tmp, "results.csv")
        with open(csv_path, "w") as f:
            f.write(",".join(HEADER) + "\n")
            for scene, config, renderer, aa, ss, timed, ms, rmse, pareto in ROWS:
                f.write(",".join([scene, "100", "100", "48", "480", "360", config, renderer, aa, ss, timed,
                                  "3" if timed == "1" else "0", ms, rmse, pareto, "gstd"]) + "\n")
        run = subprocess.run([py, SCRIPT, csv_path, tmp], capture_output=True, text=True)
        if run.returncode != 0:
            print(run.stdout + run.stderr)
            print(f"chart_test: FAIL: bench_chart.py exited {run.returncode}")
            return 1
        for name in ("chart.png", "chart.svg"):
            path = os.path.join(tmp, name)
            if not os.path.isfile(path) or os.path.getsize(path) == 0:
                failures.append(f"{name} missing or empty")
        leftovers = [n for n in os.listdir(tmp) if ".tmp." in n]
        if leftovers:
            failures.append(f"temporary files left: {leftovers}")
        svg = open(os.path.join(tmp, "chart.svg")).read() if os.path.isfile(os.path.join(tmp, "chart.svg")) else ""

        plain = re.compile(r"^-?\d{1,3}(,\d{3})*(\.\d+)?$|^-?\d+(\.\d+)?$")
        xs, ys = tick_labels(svg, "x"), tick_labels(svg, "y")
        if len(xs) < 4 or len(ys) < 4:
            failures.append(f"too few tick labels found in the SVG (x {xs}, y {ys})")
        for label in xs + ys:
            if not plain.match(label):
                failures.append(f"tick label {label!r} is not a plain number")
        # Offset or scientific notation anywhere in the SVG's texts.
        texts = re.findall(r"<!-- (.*?) -->", svg)
        for t in texts:
            if re.search(r"^[+\u2212-]\s*\d", t) or "\\times" in t or "\u00d7" in t or "10^" in t \
                    or re.search(r"\d[eE][+-]?\d", t):
                failures.append(f"offset or scientific notation in text {t!r}")
        if "+3.44" in svg:
            failures.append("offset text +3.44 in the SVG")
        # The error axis starts at 0 in both panels (no zoom into a 0.00014 range).
        if ys.count("0") < 2:
            failures.append(f"error axes do not both start at 0: y tick labels {ys}")
        # Near-equal errors are called equal in the panel.
        if not any("equal" in t for t in texts):
            failures.append("no note that the near-equal errors are equal")
        if not any(t.startswith("better") for t in texts):
            failures.append("no 'better' mark")
    if failures:
        for f in failures:
            print("chart_test: FAIL: " + f)
        return 1
    print("chart_test: OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
