#!/usr/bin/env python3
"""simplify-sweep.sh's chart: frame time against the EIA error against the gold standard.

    simplify_chart.py TABLE.csv SCENE OUTDIR

Reads the sweep's table.csv and writes OUTDIR/chart.svg (plain SVG, always) and
OUTDIR/chart.png (matplotlib, where it is installed: Debian python3-matplotlib). One point
per --simplify level and renderer (mvr, lfdpr), labelled with the level in view pixels:
median ms per frame (log axis) against the RMSE (0..255) of the renderer's EIA against gstd
rendered from the unsimplified pack. The error axis starts at 0 (identical to the gold
standard); the dotted line per renderer is its error at --simplify 0 (the method's own), so
the height above it is what simplification adds. Lower left is better (faster, closer).
Colours as lfd-bench's chart (player/bench/bench_chart.py).
"""
import csv
import math
import os
import sys

COLOURS = {"mvr": "#1f77b4", "lfdpr": "#d62728"}


def series(rows):
    for renderer in ("mvr", "lfdpr"):
        yield renderer, [(float(r[f"{renderer}_ms"]), float(r[f"{renderer}_vs_gstd_rmse"]), r["simplify_px"]) for r in rows]


def write_svg(rows, scene, path):
    W, H, L, R, T, B = 680, 420, 70, 150, 44, 50
    ms = [float(r[k]) for r in rows for k in ("mvr_ms", "lfdpr_ms")]
    lo, hi = math.log10(min(ms)) - 0.1, math.log10(max(ms)) + 0.1
    emax = max(float(r[k]) for r in rows for k in ("mvr_vs_gstd_rmse", "lfdpr_vs_gstd_rmse")) * 1.15 or 1.0
    x = lambda v: L + (math.log10(v) - lo) / (hi - lo) * (W - L - R)
    y = lambda e: H - B - e / emax * (H - T - B)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
           f'<rect width="{W}" height="{H}" fill="white"/>',
           f'<text x="{L}" y="20" font-size="14">{scene}: lfd-bake --simplify levels, EIA error against gstd of --simplify 0</text>',
           f'<line x1="{L}" y1="{H-B}" x2="{W-R}" y2="{H-B}" stroke="black"/><line x1="{L}" y1="{T}" x2="{L}" y2="{H-B}" stroke="black"/>',
           f'<text x="{(L+W-R)/2}" y="{H-12}" text-anchor="middle">median ms per frame (log)</text>',
           f'<text x="14" y="{(T+H-B)/2}" transform="rotate(-90 14 {(T+H-B)/2})" text-anchor="middle">EIA RMSE vs gstd (0..255)</text>']
    for e in range(int(math.floor(lo)), int(math.ceil(hi)) + 1):
        for m in (1, 2, 5):
            v = m * 10 ** e
            if lo <= math.log10(v) <= hi:
                out.append(f'<line x1="{x(v):.1f}" y1="{H-B}" x2="{x(v):.1f}" y2="{H-B+4}" stroke="black"/><text x="{x(v):.1f}" y="{H-B+16}" text-anchor="middle">{v:g}</text>')
    for i in range(6):
        e = i * emax / 5
        out.append(f'<line x1="{L-4}" y1="{y(e):.1f}" x2="{L}" y2="{y(e):.1f}" stroke="black"/><text x="{L-6}" y="{y(e)+4:.1f}" text-anchor="end">{e:.1f}</text>')
    for k, (renderer, pts) in enumerate(series(rows)):
        c = COLOURS[renderer]
        out.append(f'<line x1="{L}" y1="{y(pts[0][1]):.1f}" x2="{W-R}" y2="{y(pts[0][1]):.1f}" stroke="{c}" stroke-dasharray="2 3"/>')
        out.append('<polyline fill="none" stroke="%s" points="%s"/>' % (c, " ".join(f"{x(a):.1f},{y(b):.1f}" for a, b, _ in pts)))
        for a, b, level in pts:
            out.append(f'<circle cx="{x(a):.1f}" cy="{y(b):.1f}" r="4" fill="{c}"/><text x="{x(a)+6:.1f}" y="{y(b)-6:.1f}" fill="{c}">{level}</text>')
        ly = T + 20 * (k + 1)
        out.append(f'<circle cx="{W-R+15}" cy="{ly}" r="4" fill="{c}"/><text x="{W-R+24}" y="{ly+4}">{renderer}</text>')
    out.append(f'<text x="{W-R+10}" y="{T+70}" fill="#666">labels: --simplify px</text>')
    out.append(f'<text x="{W-R+10}" y="{T+88}" fill="#666">dotted: at --simplify 0</text>')
    out.append(f'<text x="{W-R+10}" y="{T+106}" fill="#666">lower left is better</text>')
    out.append("</svg>")
    with open(path + ".tmp", "w") as f:
        f.write("\n".join(out) + "\n")
    os.replace(path + ".tmp", path)


def write_png(rows, scene, path):
    try:
        import matplotlib
    except ImportError:
        print("simplify_chart: no matplotlib (Debian: python3-matplotlib), chart.png skipped", file=sys.stderr)
        return
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import FixedLocator, FuncFormatter, NullFormatter

    fig, ax = plt.subplots(figsize=(7.2, 4.6), dpi=120)
    for renderer, pts in series(rows):
        c = COLOURS[renderer]
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        ax.axhline(ys[0], color=c, linestyle=":", linewidth=0.9, alpha=0.7)
        ax.plot(xs, ys, "-o", color=c, label=renderer, markersize=5)
        for a, b, level in pts:
            ax.annotate(f"{level}", (a, b), textcoords="offset points", xytext=(5, 5), fontsize=8, color=c)
    ax.set_xscale("log")
    ms = [float(r[k]) for r in rows for k in ("mvr_ms", "lfdpr_ms")]
    ticks = [m * 10 ** e for e in range(0, 6) for m in (1, 2, 5) if min(ms) / 1.3 <= m * 10 ** e <= max(ms) * 1.3]
    ax.xaxis.set_major_locator(FixedLocator(ticks))
    ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.set_xlim(min(ms) / 1.3, max(ms) * 1.3)
    emax = max(float(r[k]) for r in rows for k in ("mvr_vs_gstd_rmse", "lfdpr_vs_gstd_rmse"))
    ax.set_ylim(0, emax * 1.2)
    ax.set_xlabel("median ms per frame (log)")
    ax.set_ylabel("EIA RMSE against gstd of --simplify 0 (0..255)")
    ax.set_title(f"{scene}: lfd-bake --simplify levels (labels: view px)", fontsize=10)
    ax.grid(True, which="major", alpha=0.3)
    ax.annotate("better", xy=(0.04, 0.06), xytext=(0.16, 0.22), xycoords="axes fraction",
                arrowprops=dict(arrowstyle="->", color="#555"), color="#555", fontsize=8)
    ax.legend(title="dotted: --simplify 0", fontsize=8, title_fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig(path + ".tmp.png")
    plt.close(fig)
    os.replace(path + ".tmp.png", path)


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    rows = list(csv.DictReader(open(sys.argv[1])))
    write_svg(rows, sys.argv[2], os.path.join(sys.argv[3], "chart.svg"))
    write_png(rows, sys.argv[2], os.path.join(sys.argv[3], "chart.png"))


if __name__ == "__main__":
    main()
