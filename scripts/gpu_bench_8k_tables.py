#!/usr/bin/env python3
"""The tables of gpu-bench-8k.sh: OUTDIR/8k.md (per run and renderer: stage times, wall
time, lfdpr/mvr, EIA SSIM, GL calls, frame GPU MiB) and OUTDIR/8k-work.md (lfdpr's work
counters from the counted frame, docs/player/8k-panels.md "Work counters").

Usage: gpu_bench_8k_tables.py OUTDIR RUN... -- SKIPPED...
"""
import json
import os
import sys

WORK = ["work_points", "work_point_views", "work_point_views_culled", "work_point_views_culled_by_centres",
        "work_point_view_setups", "work_samples", "work_atomics", "work_words_lowered", "work_shadings",
        "work_bytes_cleared"]


def fmt(v, spec="{:.2f}"):
    return "-" if v is None else spec.format(v)


def load(out, run):
    path = os.path.join(out, "8k", run, "bench.json")
    return json.load(open(path)) if os.path.exists(path) else None


def stage(r, name):
    st = r.get("stages", {}).get(name)
    return st["mean"] if st else None


def times_table(out, runs, skipped):
    lines = []
    first = next((b for b in (load(out, r) for r in runs) if b), None)
    if first:
        lines.append(f"GPU / driver: {first['gl']}\n")
    lines.append("| run | views | renderer | point gen ms (points) | view gen ms | resolve ms | EIA ms | total ms | "
                 "wall ms/frame | vs mvr | EIA SSIM vs mvr | dispatches / barriers / waits | frame GPU MiB |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for run in runs:
        b = load(out, run)
        if not b and run.endswith("-p0"):
            continue  # the prototype: counted only (gpu-bench.sh's table.md has its times)
        if not b:
            lines.append(f"| {run} | - | (no bench.json) | | | | | | | | | | |")
            continue
        p = b["profile"]
        totals = {r["name"]: stage(r, "total") for r in b["renderers"]}
        for r in b["renderers"]:
            if not r.get("timed"):
                continue
            t = totals[r["name"]]
            pts = r.get("extra", {}).get("points")
            pg = stage(r, "point_generation")
            pgs = "-" if pg is None else (f"{pg:.2f} ({pts / 1e6:.2f}M)" if pts else f"{pg:.2f}")
            vs = "-" if not totals.get("mvr") or not t else f"{totals['mvr'] / t:.2f}x"
            calls = r.get("gl_calls_per_frame", {})
            shape = f"{calls.get('dispatches', 0):.0f} / {calls.get('barriers', 0):.0f} / {calls.get('waits', 0):.0f}"
            ssim = r.get("quality", {}).get("eia", {}).get("ssim")
            lines.append(f"| {run} | {p['views']} x {p['view_width']}x{p['view_height']} | {r['name']} | {pgs} | "
                         f"{fmt(stage(r, 'view_generation'))} | {fmt(stage(r, 'resolve'))} | {fmt(stage(r, 'eia'))} | "
                         f"{fmt(t)} | {fmt(r.get('wall_ms_per_frame'))} | {vs} | {fmt(ssim, '{:.6f}')} | {shape} | "
                         f"{r.get('frame_gpu_bytes', 0) / 2**20:.0f} |")
    if skipped:
        lines.append(f"\nleft out (past the time budget): {', '.join(skipped)}")
    return "\n".join(lines) + "\n"


def work_table(out, runs):
    lines = ["| run | " + " | ".join(w[len("work_"):] for w in WORK) + " |",
             "|---|" + "---:|" * len(WORK)]
    for run in runs:
        path = os.path.join(out, "8k", run + "-work", "bench.json")
        if not os.path.exists(path):
            continue
        b = json.load(open(path))
        for r in b["renderers"]:
            if r["name"] != "lfdpr":
                continue
            e = r.get("extra", {})
            lines.append(f"| {run} | " + " | ".join(fmt(e.get(w), "{:.0f}") for w in WORK) + " |")
    return "\n".join(lines) + "\n"


def main():
    out = sys.argv[1]
    args = sys.argv[2:]
    cut = args.index("--") if "--" in args else len(args)
    runs, skipped = args[:cut], args[cut + 1:]
    for name, text in (("8k.md", times_table(out, runs, skipped)), ("8k-work.md", work_table(out, runs))):
        tmp = os.path.join(out, name + ".tmp")
        with open(tmp, "w") as f:
            f.write(text)
        os.replace(tmp, os.path.join(out, name))
        print(f"== {name}\n{text}")


if __name__ == "__main__":
    main()
