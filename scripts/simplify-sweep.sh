#!/usr/bin/env bash
# The simplification axis (issue 40; README "Simplification"): bakes one glTF scene at
# `lfd-bake --simplify` 0, 0.25, 0.5, 1 and 2 view pixels, times mvr and lfdpr on every
# pack with lfd-bench, and compares each level's EIA with the unsimplified pack's mvr EIA
# (the reference every level is judged by: what the scene looked like before
# simplification). Writes OUT/table.md (and table.csv): triangles, vertices, pack size,
# simplification time, median frame times, and the SSIM / RMSE of mvr's EIA against level 0's and
# of lfdpr's against mvr's on the same pack.
#
#   scripts/simplify-sweep.sh SCENE.gltf OUT [BUILD_DIR] [-- extra lfd-bench flags]
#
# Levels: SIMPLIFY_LEVELS (default "0 0.25 0.5 1 2"); frames: BENCH_FRAMES (default 3),
# BENCH_WARMUP (default 1). lfd-bench runs the renderers taking turns frame by frame, so a
# machine whose speed drifts slows them alike; the levels run one after another.
set -euo pipefail
scene=${1:?usage: simplify-sweep.sh SCENE.gltf OUT [BUILD_DIR] [-- lfd-bench flags]}
out=${2:?usage: simplify-sweep.sh SCENE.gltf OUT [BUILD_DIR] [-- lfd-bench flags]}
build=${3:-build}
shift $(( $# >= 3 ? 3 : $# ))
[[ ${1:-} == -- ]] && shift
levels=${SIMPLIFY_LEVELS:-0 0.25 0.5 1 2}
bake=${LFD_BAKE:-$build/baker/lfd-bake}
bench=${LFD_BENCH:-$build/player/lfd-bench}
compare=${LFD_COMPARE:-$build/player/metrics/lfd-compare}
mkdir -p "$out"
name=$(basename "$scene" .gltf)
name=${name%.glb}

csv=$out/table.csv
echo "simplify_px,triangles,vertices,pack_bytes,simplify_s,largest_error_px,mvr_ms,lfdpr_ms,mvr_vs_level0_ssim,mvr_vs_level0_rmse,lfdpr_vs_mvr_ssim,lfdpr_vs_mvr_rmse" > "$csv"
ref=""
for level in $levels; do
    pack=$out/${name}_s$level.lfdpack
    report=$("$bake" "$scene" -o "$pack" --simplify "$level")
    echo "$report" > "$out/bake_s$level.txt"
    triangles=$(grep -m1 '^  triangles:' <<< "$report" | sed -E 's/.* in, ([0-9]+) out.*/\1/')
    vertices=$(grep -m1 '^  triangles:' <<< "$report" | sed -E 's/.* ([0-9]+) vertices$/\1/')
    seconds=$(grep -m1 '^  time:' <<< "$report" | sed -E 's/.*simplify ([0-9.]+) s.*/\1/')
    error=$(grep -m1 '^  simplification (' <<< "$report" | sed -E 's/.*largest error ([0-9.e+-]+) view px.*/\1/' || true)
    bytes=$(stat -c %s "$pack")
    "$bench" "$pack" --renderers mvr,lfdpr --reference mvr --frames "${BENCH_FRAMES:-3}" \
        --warmup "${BENCH_WARMUP:-1}" --lens-positions 1 --quiet --out "$out/bench_s$level" "$@" > /dev/null
    # Mean total ms per renderer from lfd-bench's results.csv (columns by header name).
    ms() { python3 - "$out/bench_s$level/results.csv" "$1" <<'PY'
import csv, sys
for row in csv.DictReader(open(sys.argv[1])):
    if row.get("renderer") == sys.argv[2]:
        print(row.get("total_median_ms", "")); break
PY
    }
    mvr_ms=$(ms mvr)
    lfdpr_ms=$(ms lfdpr)
    [[ -z $ref ]] && ref=$out/bench_s$level/mvr_eia.png
    cmp() { "$compare" --json "$1" "$2" | python3 -c 'import json,sys; j=json.load(sys.stdin); print("%.4f,%.3f" % (j["ssim"], j["rmse"]))'; }
    vs0=$(cmp "$ref" "$out/bench_s$level/mvr_eia.png")
    lvm=$(cmp "$out/bench_s$level/mvr_eia.png" "$out/bench_s$level/lfdpr_eia.png")
    echo "$level,$triangles,$vertices,$bytes,$seconds,${error:-0},$mvr_ms,$lfdpr_ms,$vs0,$lvm" >> "$csv"
    echo "simplify $level: $triangles triangles, mvr $mvr_ms ms, lfdpr $lfdpr_ms ms, mvr vs level 0 $vs0, lfdpr vs mvr $lvm" >&2
done

python3 - "$csv" "$name" > "$out/table.md" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
base = rows[0]
print(f"# {sys.argv[2]}: `lfd-bake --simplify` levels\n")
print("| --simplify (view px) | triangles | vertices | pack | simplify s | largest error px | mvr median ms (speed-up) | lfdpr median ms (speed-up) | mvr EIA vs level 0: SSIM / RMSE | lfdpr EIA vs mvr: SSIM / RMSE |")
print("|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    sp = lambda k: f"{float(base[k]) / float(r[k]):.2f}x" if r[k] and float(r[k]) > 0 else "-"
    print(f"| {r['simplify_px']} | {int(r['triangles']):,} | {int(r['vertices']):,} | {int(r['pack_bytes']) / 2**20:.1f} MiB | {r['simplify_s']} | {r['largest_error_px']} "
          f"| {float(r['mvr_ms']):.0f} ({sp('mvr_ms')}) | {float(r['lfdpr_ms']):.0f} ({sp('lfdpr_ms')}) "
          f"| {r['mvr_vs_level0_ssim']} / {r['mvr_vs_level0_rmse']} | {r['lfdpr_vs_mvr_ssim']} / {r['lfdpr_vs_mvr_rmse']} |")
PY


# OUT/chart.svg: frame time (log scale) against mvr's EIA SSIM to level 0, one point per
# level and renderer, so the level where the error starts to show and what each level
# buys read off one picture. Plain SVG (no plotting package needed).
python3 - "$csv" "$name" > "$out/chart.svg" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
W, H, L, R, T, B = 640, 400, 70, 150, 40, 50
ms = [float(r[k]) for r in rows for k in ("mvr_ms", "lfdpr_ms")]
lo, hi = math.log10(min(ms)) - 0.1, math.log10(max(ms)) + 0.1
ss = [float(r["mvr_vs_level0_ssim"]) for r in rows]
slo = min(min(ss), 0.99) - 0.001
x = lambda v: L + (math.log10(v) - lo) / (hi - lo) * (W - L - R)
y = lambda s: T + (1.0 - s) / (1.0 - slo) * (H - T - B)
out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
       f'<rect width="{W}" height="{H}" fill="white"/>',
       f'<text x="{L}" y="20" font-size="14">{sys.argv[2]}: lfd-bake --simplify levels (frame time vs EIA SSIM to --simplify 0)</text>',
       f'<line x1="{L}" y1="{H-B}" x2="{W-R}" y2="{H-B}" stroke="black"/><line x1="{L}" y1="{T}" x2="{L}" y2="{H-B}" stroke="black"/>',
       f'<text x="{(L+W-R)/2}" y="{H-12}" text-anchor="middle">median frame ms (log)</text>',
       f'<text x="14" y="{(T+H-B)/2}" transform="rotate(-90 14 {(T+H-B)/2})" text-anchor="middle">SSIM of mvr EIA vs level 0</text>']
for e in range(int(math.floor(lo)), int(math.ceil(hi)) + 1):
    for m in (1, 2, 5):
        v = m * 10 ** e
        if lo <= math.log10(v) <= hi:
            out.append(f'<line x1="{x(v):.1f}" y1="{H-B}" x2="{x(v):.1f}" y2="{H-B+4}" stroke="black"/><text x="{x(v):.1f}" y="{H-B+16}" text-anchor="middle">{v:g}</text>')
for i in range(5):
    s = 1.0 - i * (1.0 - slo) / 4
    out.append(f'<line x1="{L-4}" y1="{y(s):.1f}" x2="{L}" y2="{y(s):.1f}" stroke="black"/><text x="{L-6}" y="{y(s)+4:.1f}" text-anchor="end">{s:.4f}</text>')
out.append(f'<line x1="{L}" y1="{y(0.99):.1f}" x2="{W-R}" y2="{y(0.99):.1f}" stroke="#999" stroke-dasharray="4 3"/><text x="{W-R+4}" y="{y(0.99)+4:.1f}" fill="#666">SSIM 0.99</text>')
for key, colour, label in (("mvr_ms", "#1f77b4", "mvr"), ("lfdpr_ms", "#d62728", "lfdpr")):
    pts = [(x(float(r[key])), y(float(r["mvr_vs_level0_ssim"]) if key == "mvr_ms" else min(1.0, float(r["mvr_vs_level0_ssim"])))) for r in rows]
    out.append('<polyline fill="none" stroke="%s" points="%s"/>' % (colour, " ".join(f"{a:.1f},{b:.1f}" for a, b in pts)))
    for (a, b), r in zip(pts, rows):
        out.append(f'<circle cx="{a:.1f}" cy="{b:.1f}" r="4" fill="{colour}"/><text x="{a+6:.1f}" y="{b-6:.1f}" fill="{colour}">{r["simplify_px"]}</text>')
    ly = T + 20 * (1 if label == "mvr" else 2)
    out.append(f'<circle cx="{W-R+15}" cy="{ly}" r="4" fill="{colour}"/><text x="{W-R+24}" y="{ly+4}">{label}</text>')
out.append(f'<text x="{W-R+10}" y="{T+70}" fill="#666">labels: --simplify px</text>')
out.append('</svg>')
print("\n".join(out))
PY
cat "$out/table.md"
