#!/usr/bin/env python3
"""lfd-bench's matrix chart: time per frame against error, one panel per scene.

    bench_chart.py RESULTS.csv OUTDIR

Reads lfd-bench's results.csv and writes OUTDIR/chart.png and OUTDIR/chart.svg: per scene
(and view count) one panel with the total GPU ms per frame (log axis) against the EIA RMSE
against the reference, one labelled point per configuration (colour = renderer, marker =
supersampling), and the Pareto front (configurations no other beats in both) drawn as a
step line. Needs matplotlib (Debian: python3-matplotlib); lfd-bench runs it and skips the
chart, saying why, where it is missing.
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLOURS = {"mvr": "#1f77b4", "mvr-layered": "#17becf", "lfdpr": "#d62728", "lfdpr-paper": "#ff7f0e",
           "gstd": "#7f7f7f"}
MARKERS = {"1": "o", "2s": "s", "2v": "^"}


def short_label(row):
    aa = {"none": "", "spatial": "Sp", "view": "Vi", "view-spatial": "ViSp"}.get(row["aa"], row["aa"])
    parts = [row["renderer"]]
    if aa:
        parts.append(aa + " AA")
    if row["ss"] != "1":
        parts.append("SS " + row["ss"])
    return " ".join(parts)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: bench_chart.py RESULTS.csv OUTDIR")
    with open(sys.argv[1], newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["timed"] == "1" and r["total_ms"] and r["eia_rmse"]]
    panels = {}
    for r in rows:
        panels.setdefault((r["scene"], r["views"], r["view_width"], r["view_height"]), []).append(r)
    if not panels:
        sys.exit("bench_chart.py: no timed configurations in " + sys.argv[1])

    n = len(panels)
    cols = min(n, 3)
    rows_n = math.ceil(n / cols)
    fig, axes = plt.subplots(rows_n, cols, figsize=(6.2 * cols, 4.6 * rows_n), squeeze=False)
    reference = rows[0]["reference"]
    for ax, ((scene, views, w, h), pts) in zip(axes.flat, panels.items()):
        for p in pts:
            colour = COLOURS.get(p["renderer"], "#2ca02c")
            ax.scatter(float(p["total_ms"]), float(p["eia_rmse"]), c=colour,
                       marker=MARKERS.get(p["ss"], "o"), s=46, zorder=3,
                       edgecolors="black" if p["pareto"] == "1" else "none")
        for i, p in enumerate(sorted(pts, key=lambda q: (float(q["eia_rmse"]), float(q["total_ms"])))):
            colour = COLOURS.get(p["renderer"], "#2ca02c")
            # Alternate label sides so close points stay readable.
            ax.annotate(short_label(p), (float(p["total_ms"]), float(p["eia_rmse"])), textcoords="offset points",
                        xytext=(6, 3 if i % 2 == 0 else -9), fontsize=7, color=colour)
        front = sorted((float(p["total_ms"]), float(p["eia_rmse"])) for p in pts if p["pareto"] == "1")
        if front:
            xs, ys = zip(*front)
            ax.step(xs, ys, where="post", color="black", linewidth=1.0, linestyle="--", zorder=2,
                    label="Pareto front")
            ax.legend(loc="upper right", fontsize=7)
        ax.set_xscale("log")
        ax.set_title(f"{scene}: {views} views of {w}x{h}", fontsize=10)
        ax.set_xlabel("total GPU time per frame, ms (log)")
        ax.set_ylabel(f"EIA RMSE against {reference} (0..255)")
        ax.grid(True, which="both", alpha=0.3)
        ax.margins(x=0.25, y=0.15)
    for ax in list(axes.flat)[n:]:
        ax.axis("off")
    fig.suptitle("lfd-bench: time per frame against error\nmarker: circle no SS, square 2x spatial SS, "
                 "triangle 2x angular SS; outlined = on the Pareto front", fontsize=9)
    # Half an inch on top for the two-line title (tight_layout ignores suptitle).
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.5 / fig.get_figheight()))
    out = sys.argv[2]
    for ext in ("png", "svg"):
        path = os.path.join(out, "chart." + ext)
        tmp = path + ".tmp." + ext
        fig.savefig(tmp, dpi=110)
        os.replace(tmp, path)


if __name__ == "__main__":
    main()
