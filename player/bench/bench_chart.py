#!/usr/bin/env python3
"""lfd-bench's matrix chart: time per frame against error, one panel per scene.

    bench_chart.py RESULTS.csv OUTDIR [--error COLUMN]

COLUMN is the error plotted (default eia_rmse, the EIA against the reference); the
through-the-lens sweep's lens_sweep_rmse_mean or lens_sweep_rmse_worst (or any RMSE column
of results.csv) plot what a viewer sees across the viewing cone instead, with the Pareto
front recomputed for that error.

Reads lfd-bench's results.csv and writes OUTDIR/chart.png and OUTDIR/chart.svg (each
atomically): per scene and view count one panel with the total GPU ms per frame against the
EIA RMSE against the reference, one point per configuration and the Pareto front (the
configurations no other beats in both time and error) drawn as a step line: for a time
budget T, the front's height at T is the lowest error any configuration reaches within T.

Reading aids, because the chart is read by people who have not seen this code:
* Both axes show plain numbers (no offset or scientific notation). The error axis starts
  at 0 (identical to the reference), so errors that differ in the fourth decimal look
  equal; a note in the panel says so where they are. The time axis is linear from 0 where
  a panel's times span less than 3x, else logarithmic with a few 1-2-5 ticks that are
  checked not to overlap.
* Colour = renderer, marker = supersampling (--ss), fill = reconstruction (--aa); one
  legend for the figure names every configuration as table.md does ("lfdpr SS 2v",
  "mvr AA view-spatial SS 2s"). Points on the Pareto front are ringed and labelled with
  that name, placed where no other text or point is (with a leader line where the label
  sits away from its point); the others are faded.
* Each panel has an arrow to its lower-left corner: faster and more accurate is better.
* The title names the GL device where results.json (written next to results.csv by
  lfd-bench) says it.
Needs matplotlib (Debian: python3-matplotlib; works with 3.6); lfd-bench runs it and skips
the chart, saying why, where it is missing.
"""
import csv
import json
import math
import os
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.ticker import FixedLocator, FuncFormatter, MaxNLocator, NullFormatter, ScalarFormatter  # noqa: E402
from matplotlib.transforms import Bbox  # noqa: E402

COLOURS = {"mvr": "#1f77b4", "mvr-layered": "#17becf", "lfdpr": "#d62728", "lfdpr-paper": "#ff7f0e",
           "gstd": "#7f7f7f"}
EXTRA_COLOURS = ["#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#bcbd22", "#7f7f7f", "#393b79", "#637939"]
MARKERS = {"1": "o", "2s": "s", "2v": "^"}
EXTRA_MARKERS = ["D", "v", "P", "X", "*", "h"]
# Reconstruction (--aa) as the marker's fill: none = filled, view-spatial = hollow, the
# single-axis filters half filled.
FILLS = {"none": "full", "view-spatial": "none", "spatial": "left", "view": "bottom"}
SS_ORDER = {"1": 0, "2v": 1, "2s": 2}
AA_ORDER = {"none": 0, "spatial": 1, "view": 2, "view-spatial": 3}
RENDERER_ORDER = {"mvr": 0, "mvr-layered": 1, "lfdpr": 2, "lfdpr-paper": 3, "gstd": 9}

LABEL_FONT = 7.0
TICK_FONT = 8.0


def config_name(r):
    """results.csv's configuration name (lfdpr+aa-view-spatial+ss-2v), the key of a configuration."""
    if r.get("config"):
        return r["config"]
    name = r["renderer"]
    if r.get("aa", "none") != "none":
        name += "+aa-" + r["aa"]
    if r.get("ss", "1") != "1":
        name += "+ss-" + r["ss"]
    return name


def display_name(r):
    """What the chart calls a configuration, in table.md's terms: renderer, AA (--aa), SS (--ss),
    e.g. "lfdpr SS 2v", "mvr AA view-spatial SS 2s"; plain "lfdpr" is AA none, SS 1."""
    name = r["renderer"]
    if r.get("aa", "none") != "none":
        name += " AA " + r["aa"]
    if r.get("ss", "1") != "1":
        name += " SS " + r["ss"]
    return name


class Styles:
    """Colour per renderer, marker per --ss, fill per --aa; unknown names get the next free one."""

    def __init__(self):
        self.colours = dict(COLOURS)
        self.markers = dict(MARKERS)
        self.fills = dict(FILLS)

    def colour(self, renderer):
        if renderer not in self.colours:
            used = set(self.colours.values())
            free = [c for c in EXTRA_COLOURS if c not in used] or EXTRA_COLOURS
            self.colours[renderer] = free[0]
        return self.colours[renderer]

    def marker(self, ss):
        if ss not in self.markers:
            used = set(self.markers.values())
            free = [m for m in EXTRA_MARKERS if m not in used] or EXTRA_MARKERS
            self.markers[ss] = free[0]
        return self.markers[ss]

    def fill(self, aa):
        if aa not in self.fills:
            used = set(self.fills.values())
            free = [f for f in ("right", "top") if f not in used] or ["none"]
            self.fills[aa] = free[0]
        return self.fills[aa]

    def kwargs(self, r):
        colour = self.colour(r["renderer"])
        fill = self.fill(r.get("aa", "none"))
        return dict(marker=self.marker(r.get("ss", "1")), color=colour, markeredgecolor=colour,
                    markerfacecolor=colour if fill != "none" else "white", fillstyle=fill,
                    markerfacecoloralt="white", markeredgewidth=1.4, linestyle="none")


def pareto_flags(pts):
    """The CSV's `pareto` column; computed (nothing faster and at least as accurate) if absent."""
    if all(p.get("pareto") in ("0", "1") for p in pts):
        return [p["pareto"] == "1" for p in pts]
    flags = []
    for p in pts:
        dominated = any(q is not p and q["t"] <= p["t"] and q["e"] <= p["e"] and (q["t"] < p["t"] or q["e"] < p["e"])
                        for q in pts)
        flags.append(not dominated)
    return flags


def fmt_number(v):
    """A plain number: no offset, no exponent; digits grouped with commas from 10,000."""
    if float(v).is_integer():
        return f"{int(v):,}" if abs(v) >= 10000 else str(int(v))
    return f"{v:.3f}".rstrip("0").rstrip(".")


def log_ticks(lo, hi, width_pt, char_pt):
    """The densest 1-2-5-style tick set (2 to 7 ticks) inside [lo, hi] whose labels, char_pt
    per character, leave at least 8 pt between them on an axis width_pt wide."""
    sequences = [[1, 1.5, 2, 3, 4, 5, 6, 8], [1, 1.5, 2, 3, 5, 7], [1, 2, 3, 5], [1, 2, 5], [1, 3], [1]]
    span = math.log10(hi) - math.log10(lo)
    fallback = None
    for seq in sequences:
        ticks = [m * 10 ** k for k in range(int(math.floor(math.log10(lo))) - 1, int(math.ceil(math.log10(hi))) + 1)
                 for m in seq if lo <= m * 10 ** k <= hi]
        if len(ticks) > 7:
            continue
        if len(ticks) < 2:
            fallback = fallback or ticks
            continue
        if all((math.log10(b) - math.log10(a)) / span * width_pt
               >= (len(fmt_number(a)) + len(fmt_number(b))) / 2 * char_pt + 8 for a, b in zip(ticks, ticks[1:])):
            return ticks
    # Too narrow for two labels: the ends of the range, rounded.
    return fallback or [float(f"{lo:.2g}"), float(f"{hi:.2g}")]


def nice_ceiling(v):
    if v <= 0:
        return 1.0
    e = 10 ** math.floor(math.log10(v))
    for m in (1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10):
        if m * e >= v - 1e-12:
            return m * e
    return 10 * e


def device_string(csv_path):
    """The GL string from results.json next to results.csv (lfd-bench writes both), or ''."""
    try:
        with open(os.path.join(os.path.dirname(os.path.abspath(csv_path)), "results.json")) as f:
            doc = json.load(f)
        gls = []
        for run in doc.get("runs", []):
            g = run.get("gl")
            if g and g not in gls:
                gls.append(g)
        return "; ".join(gls)
    except (OSError, ValueError, AttributeError, TypeError):
        return ""


def overlaps(box, boxes):
    return any(box.overlaps(b) for b in boxes)


def place_labels(fig, ax, items, obstacles):
    """Labels (text, x, y, colour) placed in free space around their points, leader lines when away."""
    renderer = fig.canvas.get_renderer()
    axbox = ax.get_window_extent(renderer)
    inner = Bbox.from_extents(axbox.x0 + 3, axbox.y0 + 3, axbox.x1 - 3, axbox.y1 - 3)
    to_px = fig.dpi / 72.0
    angles = [225, 180, 270, 135, 315, 45, 0, 90, 202, 247, 157, 292, 337, 22, 67, 112]
    radii = [9, 16, 26, 38, 52, 68, 86, 106]
    placed = []
    for text, x, y, colour in items:
        probe = ax.annotate(text, (x, y), textcoords="offset points", xytext=(0, 0), fontsize=LABEL_FONT,
                            color=colour, zorder=6)
        chosen = None
        for r in radii:
            for a in angles:
                dx, dy = r * math.cos(math.radians(a)), r * math.sin(math.radians(a))
                ha = "left" if dx > 2 else ("right" if dx < -2 else "center")
                va = "bottom" if dy > 2 else ("top" if dy < -2 else "center")
                probe.set_position((dx, dy))
                probe.set_ha(ha)
                probe.set_va(va)
                box = probe.get_window_extent(renderer).expanded(1.0, 1.0).padded(2)
                if not (inner.containsx(box.x0) and inner.containsx(box.x1)
                        and inner.containsy(box.y0) and inner.containsy(box.y1)):
                    continue
                if overlaps(box, obstacles) or overlaps(box, placed):
                    continue
                # The leader line must not run through another label.
                px, py = ax.transData.transform((x, y))
                lx, ly = px + dx * to_px, py + dy * to_px
                seg = Bbox.from_extents(min(px, lx), min(py, ly), max(px, lx), max(py, ly))
                if r > 12 and any(seg.overlaps(b) and _segment_hits(px, py, lx, ly, b) for b in placed):
                    continue
                chosen = (dx, dy, ha, va, box, r)
                break
            if chosen:
                break
        probe.remove()
        if not chosen:
            continue
        dx, dy, ha, va, box, r = chosen
        arrow = None
        if r > 12:
            arrow = dict(arrowstyle="-", color=colour, lw=0.6, alpha=0.8, shrinkA=1, shrinkB=4)
        ax.annotate(text, (x, y), textcoords="offset points", xytext=(dx, dy), ha=ha, va=va,
                    fontsize=LABEL_FONT, color=colour, zorder=6, arrowprops=arrow,
                    bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.85))
        placed.append(box)
    return placed


def _segment_hits(x0, y0, x1, y1, box, steps=24):
    for i in range(1, steps):
        t = i / steps
        if box.contains(x0 + (x1 - x0) * t, y0 + (y1 - y0) * t):
            return True
    return False


def header_lines(rows, device):
    """Title, the device, and how to read the marks (naming only what the chart shows)."""
    lines = ["lfd-bench: time per frame against error - lower left is better (faster and more accurate)"]
    if device:
        lines.append("device: " + device)
    key = ["colour = renderer"]
    ss = sorted({r["ss"] for r in rows}, key=lambda v: SS_ORDER.get(v, 8))
    if len(ss) > 1:
        shapes = {"o": "circle", "s": "square", "^": "triangle", "D": "diamond", "v": "down triangle",
                  "P": "plus", "X": "cross", "*": "star", "h": "hexagon"}
        words = [f"{shapes.get(MARKERS.get(v, ''), 'other')} {'none' if v == '1' else 'SS ' + v}" for v in ss]
        key.append("marker = supersampling (" + ", ".join(words) + ")")
    aa = sorted({r["aa"] for r in rows}, key=lambda v: AA_ORDER.get(v, 8))
    if len(aa) > 1:
        fills = {"full": "filled", "none": "hollow", "left": "left half filled", "bottom": "bottom half filled"}
        words = [f"{fills.get(FILLS.get(v, ''), 'other')} {'none' if v == 'none' else 'AA ' + v}" for v in aa]
        key.append("fill = reconstruction (" + ", ".join(words) + ")")
    if len(key) > 1:
        lines.append("; ".join(key))
    lines.append("Best for a time budget T: the dashed Pareto front's height at T is the lowest error reachable "
                 "within T; the labelled point at its last step before T is the configuration to use")
    return lines


ERROR_LABELS = {"eia_rmse": "EIA RMSE", "lens_rmse": "through-the-lens RMSE (centre)",
                "lens_sweep_rmse_mean": "through-the-lens RMSE, mean over the sweep",
                "lens_sweep_rmse_worst": "through-the-lens RMSE, worst position of the sweep"}


ERROR = "eia_rmse"


def parse_arguments():
    args = sys.argv[1:]
    error = "eia_rmse"
    if len(args) == 4 and args[2] == "--error":
        error = args[3]
        args = args[:2]
    if len(args) != 2 or not error.endswith("rmse") and not error.endswith("rmse_mean") \
            and not error.endswith("rmse_worst"):
        sys.exit("usage: bench_chart.py RESULTS.csv OUTDIR [--error eia_rmse|lens_sweep_rmse_mean|"
                 "lens_sweep_rmse_worst|...rmse column]")
    return args[0], args[1], error


def main():
    global ERROR
    results, out, error = parse_arguments()
    ERROR = error
    sys.argv = [sys.argv[0], results, out]
    with open(results, newline="") as f:
        reader = csv.DictReader(f)
        if error not in (reader.fieldnames or []):
            sys.exit(f"bench_chart.py: {results} has no column '{error}'")
        rows = [r for r in reader if r.get("timed") == "1" and r.get("total_ms") and r.get(error)]
    if error != "eia_rmse":
        for r in rows:
            r.pop("pareto", None)  # the CSV's front is for the EIA RMSE: recomputed for this error
    panels = {}
    for r in rows:
        try:
            r["t"], r["e"] = float(r["total_ms"]), float(r[error])
        except ValueError:
            continue
        if not (math.isfinite(r["t"]) and math.isfinite(r["e"]) and r["t"] > 0):
            continue
        r.setdefault("aa", "none")
        r.setdefault("ss", "1")
        r["aa"] = r["aa"] or "none"
        r["ss"] = r["ss"] or "1"
        panels.setdefault((r["scene"], r["views"], r["view_width"], r["view_height"]), []).append(r)
    if not panels:
        sys.exit("bench_chart.py: no timed configurations in " + sys.argv[1])
    rows = [r for pts in panels.values() for r in pts]

    styles = Styles()
    configs = {}
    for r in rows:
        configs.setdefault(config_name(r), r)
    order = sorted(configs, key=lambda c: (RENDERER_ORDER.get(configs[c]["renderer"], 5), configs[c]["renderer"],
                                           AA_ORDER.get(configs[c]["aa"], 8), SS_ORDER.get(configs[c]["ss"], 8), c))
    for c in order:  # fixed colour assignment in legend order
        styles.colour(configs[c]["renderer"])

    n = len(panels)
    cols = min(n, 3)
    rows_n = math.ceil(n / cols)
    empty = rows_n * cols - n
    panel_w, panel_h = 5.6, 4.4
    entries = len(order) + 2
    # The legend goes into the empty panel slots where it fits there, else below the panels.
    legend_cols = min(entries, 2 * empty if empty else (4 if cols >= 2 else 2), 4)
    legend_rows = math.ceil(entries / legend_cols)
    legend_in_slot = empty > 0 and 0.22 * legend_rows + 0.4 < panel_h
    legend_h = 0 if legend_in_slot else 0.5 + 0.22 * legend_rows
    device = device_string(sys.argv[1])
    fig_w = panel_w * cols
    header = header_lines(rows, device)
    # Wrap the header to the figure's width (about 0.55 em per character).
    title = textwrap.wrap(header[0], int(fig_w * 72 / (12 * 0.55)))
    notes_lines = [w for line in header[1:] for w in textwrap.wrap(line, int(fig_w * 72 / (8.5 * 0.55)))]
    title_h = 0.12 + 0.22 * len(title) + 0.17 * len(notes_lines) + 0.12
    fig_h = panel_h * rows_n + title_h + legend_h
    fig, axes = plt.subplots(rows_n, cols, figsize=(fig_w, fig_h), squeeze=False)
    reference = rows[0].get("reference") or "the reference"

    panel_info = []
    for ax, ((scene, views, w, h), pts) in zip(axes.flat, panels.items()):
        flags = pareto_flags(pts)
        ts = [p["t"] for p in pts]
        es = [p["e"] for p in pts]
        tmin, tmax = min(ts), max(ts)
        # Time axis: linear from 0 where the times span < 3x (ratios read off directly), else log.
        log_x = tmax / tmin >= 3.0
        if log_x:
            xlo, xhi = tmin / 1.35, tmax * 1.35
            ax.set_xscale("log")
        else:
            xlo, xhi = 0.0, nice_ceiling(tmax * 1.12)
        ax.set_xlim(xlo, xhi)
        # Error axis from 0 (= identical to the reference): near-equal errors look near-equal.
        ylo, yhi = 0.0, nice_ceiling(max(es) * 1.25 if max(es) > 0 else 1.0)
        ax.set_ylim(ylo, yhi)
        yfmt = ScalarFormatter(useOffset=False)
        yfmt.set_scientific(False)
        ax.yaxis.set_major_locator(MaxNLocator(nbins=6, steps=[1, 2, 2.5, 5, 10]))
        ax.yaxis.set_major_formatter(yfmt)
        ax.tick_params(labelsize=TICK_FONT)

        # Pareto front: a step line, extended to the right edge (more time buys nothing more).
        front = sorted((p["t"], p["e"]) for p, f in zip(pts, flags) if f)
        if front:
            xs = [t for t, _ in front] + [xhi]
            ys = [e for _, e in front] + [front[-1][1]]
            ax.step(xs, ys, where="post", color="black", linewidth=1.1, linestyle="--", zorder=2, alpha=0.75)
        for p, f in zip(pts, flags):
            kw = styles.kwargs(p)
            if f:
                ax.plot([p["t"]], [p["e"]], marker="o", markersize=15, markerfacecolor="#fff3b0",
                        markeredgecolor="black", markeredgewidth=0.9, linestyle="none", zorder=3, clip_on=False)
                ax.plot([p["t"]], [p["e"]], markersize=8, zorder=4, clip_on=False, **kw)
            else:
                ax.plot([p["t"]], [p["e"]], markersize=7, zorder=4, alpha=0.45, clip_on=False, **kw)

        ax.set_title(f"{scene}: {views} views of {w}x{h}", fontsize=10)
        ax.set_xlabel("total GPU time per frame, ms" + (" (log scale)" if log_x else ""), fontsize=8.5)
        ax.set_ylabel(f"{ERROR_LABELS.get(ERROR, ERROR)} against {reference} (0..255)", fontsize=8.5)
        ax.grid(True, which="major", alpha=0.3)

        # Points at the same height: say that their errors are equal, not just close.
        notes = []
        spread = max(es) - min(es)
        if len(pts) > 1 and spread <= 0.01 * max(es):
            notes.append(f"all errors within {spread:.4f} RMSE\nof each other: equal error, compare times")
        else:
            close = 0.0
            for i, a in enumerate(es):
                for b in es[i + 1:]:
                    d = abs(a - b)
                    if d <= 0.001 * max(a, b):
                        close = max(close, d)
            if close > 0 or any(es.count(e) > 1 for e in es):
                notes.append("points side by side at one height: errors\n"
                             + (f"equal within {close:.4f} RMSE" if close > 0 else "identical"))
        panel_info.append((ax, pts, flags, log_x, notes))

    for ax in list(axes.flat)[n:]:
        ax.axis("off")

    # Figure legend: every configuration, then the front and the ring.
    handles = []
    for c in order:
        r = configs[c]
        kw = styles.kwargs(r)
        handles.append(Line2D([], [], markersize=7.5, label=display_name(r), **kw))
    handles.append(Line2D([], [], color="black", linestyle="--", linewidth=1.1,
                          label="Pareto front: lowest error within a time budget"))
    handles.append(Line2D([], [], marker="o", markersize=12, markerfacecolor="#fff3b0", markeredgecolor="black",
                          markeredgewidth=0.9, linestyle="none", label="on the front (labelled); faded: beaten"))
    # Time ticks that fit (the axes' width estimated before the layout; 8 pt of slack per label).
    for ax, pts, flags, log_x, notes in panel_info:
        width_pt = (panel_w - 0.95) * 72.0
        xlo, xhi = ax.get_xlim()
        fmt = FuncFormatter(lambda v, _pos: fmt_number(v))
        if log_x:
            ax.xaxis.set_major_locator(FixedLocator(log_ticks(xlo, xhi, width_pt, TICK_FONT * 0.62)))
            ax.xaxis.set_minor_formatter(NullFormatter())
        else:
            ax.xaxis.set_major_locator(MaxNLocator(nbins=6, steps=[1, 2, 2.5, 5, 10]))
        ax.xaxis.set_major_formatter(fmt)
        ax.set_xlim(xlo, xhi)

    fig.text(0.5, 1 - 0.08 / fig_h, "\n".join(title), ha="center", va="top", fontsize=12)
    for i, line in enumerate(notes_lines):
        fig.text(0.5, 1 - (0.14 + 0.22 * len(title) + 0.17 * i) / fig_h, line, ha="center", va="top", fontsize=8.5,
                 color="0.25")
    fig.tight_layout(rect=(0, legend_h / fig_h, 1, 1 - title_h / fig_h), h_pad=1.6, w_pad=1.4)
    legend_kw = dict(handles=handles, ncol=legend_cols, fontsize=8, frameon=True, handletextpad=0.4,
                     columnspacing=1.6, title="configuration: renderer, AA = --aa reconstruction, SS = --ss supersampling", title_fontsize=8.5)
    if legend_in_slot:
        slots = list(axes.flat)[n:]
        x0 = min(ax.get_position().x0 for ax in slots)
        x1 = max(ax.get_position().x1 for ax in slots)
        y0 = min(ax.get_position().y0 for ax in slots)
        y1 = max(ax.get_position().y1 for ax in slots)
        fig.legend(loc="center", bbox_to_anchor=((x0 + x1) / 2, (y0 + y1) / 2), **legend_kw)
    else:
        fig.legend(loc="lower center", bbox_to_anchor=(0.5, 0.1 / fig_h), **legend_kw)

    # Now that the layout is fixed: the "better" arrow, the notes and the labels, in free space.
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    for ax, pts, flags, log_x, notes in panel_info:
        obstacles = []
        # Better: an arrow to the lower-left corner.
        ann = ax.annotate("better", xy=(0.03, 0.04), xycoords="axes fraction", xytext=(0.13, 0.17),
                          textcoords="axes fraction", fontsize=8, color="#2a7a2a", fontweight="bold",
                          ha="left", va="bottom", zorder=5,
                          arrowprops=dict(arrowstyle="-|>", color="#2a7a2a", lw=1.6, shrinkA=0, shrinkB=0))
        obstacles.append(ann.get_window_extent(renderer).padded(2))
        corner = ax.transAxes.transform([(0.02, 0.03), (0.15, 0.18)])
        obstacles.append(Bbox(corner))
        marks = []
        for p in pts:
            px, py = ax.transData.transform((p["t"], p["e"]))
            marks.append(Bbox.from_extents(px - 7, py - 7, px + 7, py + 7))
        if notes:
            for nx, ny, ha, va in ((0.98, 0.97, "right", "top"), (0.02, 0.97, "left", "top"),
                                   (0.98, 0.03, "right", "bottom")):
                note = ax.text(nx, ny, notes[0], transform=ax.transAxes, ha=ha, va=va, fontsize=7,
                               color="0.3", style="italic", zorder=5,
                               bbox=dict(boxstyle="round,pad=0.25", fc="#f4f4f4", ec="0.8"))
                box = note.get_window_extent(renderer).padded(2)
                if not overlaps(box, marks + obstacles):
                    break
                note.remove()
            else:
                note = ax.text(0.98, 0.97, notes[0], transform=ax.transAxes, ha="right", va="top", fontsize=7,
                               color="0.3", style="italic", zorder=5,
                               bbox=dict(boxstyle="round,pad=0.25", fc="#f4f4f4", ec="0.8"))
                box = note.get_window_extent(renderer).padded(2)
            obstacles.append(box)
        obstacles.extend(marks)
        items = []
        for p, f in sorted(zip(pts, flags), key=lambda pf: pf[0]["t"]):
            if f:
                items.append((display_name(p), p["t"], p["e"], styles.colour(p["renderer"])))
        place_labels(fig, ax, items, obstacles)

    out = sys.argv[2]
    for ext in ("png", "svg"):
        path = os.path.join(out, "chart." + ext)
        tmp = path + ".tmp." + ext
        fig.savefig(tmp, dpi=110)
        os.replace(tmp, path)


if __name__ == "__main__":
    main()
