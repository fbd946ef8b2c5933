#!/usr/bin/env bash
# The simplification axis (issue 40; docs/baker/simplification.md): bakes one glTF scene at
# `lfd-bake --simplify` 0, 0.25, 0.5, 1 and 2 view pixels, times mvr and lfdpr on every
# pack with lfd-bench, and compares every level's mvr and lfdpr EIA with the gold standard
# (gstd) rendered ONCE from the unsimplified (level 0) pack: what the scene looks like on
# the display before any simplification, so each number is the whole error a user sees
# (the method's plus the simplification's). gstd is rendered by lfd-bench itself, as the
# untimed `--reference gstd` of the level-0 run, at the same quality frame (lfd-bench's
# --quality-frame, default 0: time 0) and turntable state as every other level's EIAs, so
# all EIAs show the same instant. Writes OUT/table.md (and table.csv): triangles,
# vertices, pack size, simplification time, median frame times, the SSIM / RMSE of mvr's and
# lfdpr's EIA against gstd, and of mvr's against level 0's mvr (the simplification's share
# alone); OUT/chart.png (matplotlib, when /usr/bin/python3 has it) and OUT/chart.svg (plain):
# frame time against the error, one point per level and renderer.
#
#   scripts/simplify-sweep.sh SCENE.gltf OUT [BUILD_DIR] [-- extra lfd-bench flags]
#
# Levels: SIMPLIFY_LEVELS (default "0 0.25 0.5 1 2"); frames: BENCH_FRAMES (default 3),
# BENCH_WARMUP (default 1); the gold standard's flags: GSTD_FLAGS (default
# "--gstd-model views --gstd-factor 2": the paper's GStd, 2 sub-views per view at twice the
# view resolution, minutes rather than the panel model's tens of minutes for a 2M-triangle
# scene on llvmpipe). lfd-bench runs the renderers taking turns frame by frame, so a machine
# whose speed drifts slows them alike; the levels run one after another.
set -euo pipefail
scene=${1:?usage: simplify-sweep.sh SCENE.gltf OUT [BUILD_DIR] [-- lfd-bench flags]}
out=${2:?usage: simplify-sweep.sh SCENE.gltf OUT [BUILD_DIR] [-- lfd-bench flags]}
build=${3:-build}
shift $(( $# >= 3 ? 3 : $# ))
[[ ${1:-} == -- ]] && shift
levels=${SIMPLIFY_LEVELS:-0 0.25 0.5 1 2}
read -r -a gstd_flags <<< "${GSTD_FLAGS:---gstd-model views --gstd-factor 2}"
bake=${LFD_BAKE:-$build/baker/lfd-bake}
bench=${LFD_BENCH:-$build/player/lfd-bench}
compare=${LFD_COMPARE:-$build/player/metrics/lfd-compare}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
name=$(basename "$scene" .gltf)
name=${name%.glb}

csv=$out/table.csv
echo "simplify_px,triangles,vertices,pack_bytes,simplify_s,largest_error_px,mvr_ms,lfdpr_ms,mvr_vs_gstd_ssim,mvr_vs_gstd_rmse,lfdpr_vs_gstd_ssim,lfdpr_vs_gstd_rmse,mvr_vs_level0_ssim,mvr_vs_level0_rmse" > "$csv"
gold=""
mvr0=""
gstd_s=""
cmp() { "$compare" --json "$1" "$2" | python3 -c 'import json,sys; j=json.load(sys.stdin); print("%.4f,%.3f" % (j["ssim"], j["rmse"]))'; }
for level in $levels; do
    pack=$out/${name}_s$level.lfdpack
    report=$("$bake" "$scene" -o "$pack" --simplify "$level")
    echo "$report" > "$out/bake_s$level.txt"
    triangles=$(grep -m1 '^  triangles:' <<< "$report" | sed -E 's/.* in, ([0-9]+) out.*/\1/')
    vertices=$(grep -m1 '^  triangles:' <<< "$report" | sed -E 's/.* ([0-9]+) vertices$/\1/')
    seconds=$(grep -m1 '^  time:' <<< "$report" | sed -E 's/.*simplify ([0-9.]+) s.*/\1/')
    error=$(grep -m1 '^  simplification (' <<< "$report" | sed -E 's/.*largest error ([0-9.e+-]+) view px.*/\1/' || true)
    bytes=$(stat -c %s "$pack")
    # The first level renders the gold standard too (untimed, after the timed frames).
    reference=(--reference mvr)
    [[ -z $gold ]] && reference=(--reference gstd --no-gstd-cache "${gstd_flags[@]}")
    start=$(date +%s)
    "$bench" "$pack" --renderers mvr,lfdpr "${reference[@]}" --frames "${BENCH_FRAMES:-3}" \
        --warmup "${BENCH_WARMUP:-1}" --lens-positions 1 --quiet --out "$out/bench_s$level" "$@" > /dev/null
    if [[ -z $gold ]]; then
        gold=$out/bench_s$level/gstd_eia.png
        mvr0=$out/bench_s$level/mvr_eia.png
        gstd_s=$(( $(date +%s) - start ))
    fi
    # Median total ms per renderer from lfd-bench's results.csv (columns by header name).
    ms() { python3 - "$out/bench_s$level/results.csv" "$1" <<'PY'
import csv, sys
for row in csv.DictReader(open(sys.argv[1])):
    if row.get("renderer") == sys.argv[2]:
        print(row.get("total_median_ms", "")); break
PY
    }
    mvr_ms=$(ms mvr)
    lfdpr_ms=$(ms lfdpr)
    mvr_gold=$(cmp "$gold" "$out/bench_s$level/mvr_eia.png")
    lfdpr_gold=$(cmp "$gold" "$out/bench_s$level/lfdpr_eia.png")
    vs0=$(cmp "$mvr0" "$out/bench_s$level/mvr_eia.png")
    echo "$level,$triangles,$vertices,$bytes,$seconds,${error:-0},$mvr_ms,$lfdpr_ms,$mvr_gold,$lfdpr_gold,$vs0" >> "$csv"
    echo "simplify $level: $triangles triangles, mvr $mvr_ms ms, lfdpr $lfdpr_ms ms, vs gstd: mvr $mvr_gold, lfdpr $lfdpr_gold; mvr vs level 0 mvr $vs0" >&2
done

settings="lfd-bench --renderers mvr,lfdpr, median of ${BENCH_FRAMES:-3} frames after ${BENCH_WARMUP:-1} warm-up, quality frame 0; gold standard: gstd ${gstd_flags[*]} from the --simplify 0 pack (${gstd_s}s for that lfd-bench run); extra lfd-bench flags: ${*:-none}"
python3 - "$csv" "$name" "$settings" > "$out/table.md" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
base = rows[0]
print(f"# {sys.argv[2]}: `lfd-bake --simplify` levels against the gold standard\n")
print(f"Settings: {sys.argv[3]}. Every EIA is compared (lfd-compare, whole panel) with gstd's EIA of the")
print("unsimplified pack; the last column isolates the simplification (mvr against mvr at level 0).\n")
print("| --simplify (view px) | triangles | vertices | pack | simplify s | largest error px | mvr median ms (speed-up) | lfdpr median ms (speed-up) | mvr EIA vs gstd: SSIM / RMSE | lfdpr EIA vs gstd: SSIM / RMSE | mvr EIA vs level 0 mvr: SSIM / RMSE |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    sp = lambda k: f"{float(base[k]) / float(r[k]):.2f}x" if r[k] and float(r[k]) > 0 else "-"
    print(f"| {r['simplify_px']} | {int(r['triangles']):,} | {int(r['vertices']):,} | {int(r['pack_bytes']) / 2**20:.1f} MiB | {r['simplify_s']} | {r['largest_error_px']} "
          f"| {float(r['mvr_ms']):.0f} ({sp('mvr_ms')}) | {float(r['lfdpr_ms']):.0f} ({sp('lfdpr_ms')}) "
          f"| {r['mvr_vs_gstd_ssim']} / {r['mvr_vs_gstd_rmse']} | {r['lfdpr_vs_gstd_ssim']} / {r['lfdpr_vs_gstd_rmse']} "
          f"| {r['mvr_vs_level0_ssim']} / {r['mvr_vs_level0_rmse']} |")
PY

# The chart: PNG through matplotlib where /usr/bin/python3 has it (docs/baker/simplification.md shows it),
# SVG always.
chart_py=python3
/usr/bin/python3 -c 'import matplotlib' 2>/dev/null && chart_py=/usr/bin/python3
"$chart_py" "$here/simplify_chart.py" "$csv" "$name" "$out"
cat "$out/table.md"
