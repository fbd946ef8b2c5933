#!/usr/bin/env bash
# The LFDPR bench table (docs/bench/gpu-h200.md): lfd-bench at the prototype's 48 views
# of 480x360 for mvr, mvr-layered, lfdpr (visibility pipeline) and lfdpr-paper on every
# scene, against mvr, plus the dense block at 96 views. Runs in two places:
#   * in a player bundle (scripts/bundle-player.sh): the bundle's lfd-bench over its
#     packs/*.lfdpack - no build tools, no baker, no source tree needed;
#   * in the source tree: builds, generates the samples (car, gallery, room, dense), bakes
#     them and the scenes of ../shared/scenes, then runs the same.
# Usage: bash gpu-bench.sh [FRAMES (default 20)] [OUTDIR (default ./gpu-bench-out in a
# bundle, out/gpu-bench in the tree)]. Per scene OUTDIR/<scene>/bench.{json,csv}; the table
# in OUTDIR/table.md (printed at the end; needs python3, else lfd-bench's own tables are
# printed). LFD_BENCH_RENDERERS times other renderers, LFD_BENCH_WARMUP sets the warm-up
# frames (default 5). Then the 8K profiles (gpu-bench-8k.sh: OUTDIR/8k.md, the work counters
# in OUTDIR/8k-work.md, prototype included), anisotropic filtering (OUTDIR/aniso.md) and
# image-based lighting's cost against the fixed light (OUTDIR/lighting.md).
# Budget: no run after the prototype table starts past LFD_BENCH_BUDGET_S seconds from the
# start (default 420: the whole call stays under 8 minutes on an H200; what is left out is
# listed). LFD_BENCH_SCENES (e.g. "car dense DamagedHelmet") keeps only those packs;
# LFD_BENCH_8K=0 skips the 8K part (LFD_BENCH_8K_* knobs: gpu-bench-8k.sh). A dry run on
# llvmpipe: LFD_BENCH_WARMUP=0 LFD_BENCH_SCENES=car bash gpu-bench.sh 1 OUTDIR.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
frames="${1:-20}"
renderers="${LFD_BENCH_RENDERERS:-mvr,mvr-layered,lfdpr,lfdpr-paper}"
warmup="${LFD_BENCH_WARMUP:-5}"
deadline="${LFD_BENCH_BUDGET_S:-420}"

if [ -x "$here/libexec/lfd-bench" ]; then
  # Bundle: prebuilt packs.
  bench="$here/lfd-bench"
  out="${2:-$PWD/gpu-bench-out}"
  profiles="$here/profiles"
  packs=("$here"/packs/*.lfdpack)
  [ -e "${packs[0]}" ] || { echo "gpu-bench: no packs in $here/packs (give them to bundle-player.sh)" >&2; exit 2; }
else
  # Source tree: build, make and bake the scenes.
  cd "$here/.."
  [ -x build/player/lfd-bench ] || bash scripts/build.sh
  bench=build/player/lfd-bench
  out="${2:-out/gpu-bench}"
  profiles="$PWD/samples/profiles"
  baked=$(bash scripts/bake-bench-scenes.sh "$out") # a failed bake stops here (set -e)
  mapfile -t packs <<<"$baked"
fi
mkdir -p "$out"
if [ -n "${LFD_BENCH_SCENES:-}" ]; then
  kept=()
  for pack in "${packs[@]}"; do
    case " $LFD_BENCH_SCENES " in *" $(basename "$pack" .lfdpack) "*) kept+=("$pack") ;; esac
  done
  [ "${#kept[@]}" -gt 0 ] || { echo "gpu-bench: no pack among LFD_BENCH_SCENES=$LFD_BENCH_SCENES" >&2; exit 2; }
  packs=("${kept[@]}")
fi

# One run per scene (and dense again at 96 views), each into its own folder.
runs=()
for pack in "${packs[@]}"; do
  scene=$(basename "$pack" .lfdpack)
  views=(48)
  [ "$scene" = dense ] && views=(48 96)
  for v in "${views[@]}"; do
    name=$scene
    [ "$v" = 48 ] || name="$scene-${v}v"
    echo "gpu-bench: $name ($v views)"
    "$bench" "$pack" --renderers "$renderers" --reference mvr --frames "$frames" --warmup "$warmup" --views "$v" \
      --view-size 480x360 --out "$out/$name" --quiet > "$out/$name.txt"
    runs+=("$name")
  done
done

if ! command -v python3 > /dev/null; then
  for name in "${runs[@]}"; do
    echo "== $name"
    cat "$out/$name.txt"
  done
  exit 0
fi
python3 - "$out" "${runs[@]}" > "$out/table.md.tmp" <<'PY'
import json, os, sys
out, runs = sys.argv[1], sys.argv[2:]
def f(v, fmt="{:.2f}"):
    return "-" if v is None else fmt.format(v)
first = json.load(open(os.path.join(out, runs[0], "bench.json")))
print(f"GPU / driver: {first['gl']}\n")
print("| scene (drawn tris) | views | renderer | point gen ms (points) | view gen ms | resolve ms | EIA ms | "
      "total ms | wall ms/frame | vs mvr | vs mvr-layered | EIA RMSE | EIA SSIM | dispatches / barriers / waits per frame | frame GPU MiB |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for run in runs:
    b = json.load(open(os.path.join(out, run, "bench.json")))
    rows = b["renderers"]
    def ms(r, stage):
        st = r.get("stages", {}).get(stage)
        return st["mean"] if st else None
    totals = {r["name"]: ms(r, "total") for r in rows}
    scene = f"{run.split('-')[0] if run.endswith('v') else run} ({b['drawn_triangles'] / 1e3:.0f}K)"
    for r in rows:
        if not r.get("timed"):
            continue
        t = totals[r["name"]]
        pts = r.get("extra", {}).get("points")
        pg = ms(r, "point_generation")
        pgs = "-" if pg is None else (f"{pg:.2f} ({pts / 1e3:.0f}K)" if pts else f"{pg:.2f}")
        vs = lambda other: "-" if not totals.get(other) or not t else f"{totals[other] / t:.2f}x"
        q = r.get("quality", {}).get("eia", {})
        calls = r.get("gl_calls_per_frame", {})
        shape = f"{calls.get('dispatches', 0):.0f} / {calls.get('barriers', 0):.0f} / {calls.get('waits', 0):.0f}"
        print(f"| {scene} | {b['profile']['views']} | {r['name']} | {pgs} | {f(ms(r, 'view_generation'))} | "
              f"{f(ms(r, 'resolve'))} | {f(ms(r, 'eia'))} | {f(t)} | {f(r.get('wall_ms_per_frame'))} | "
              f"{vs('mvr')} | {vs('mvr-layered')} | {f(q.get('rmse'))} | {f(q.get('ssim'), '{:.4f}')} | {shape} | "
              f"{r.get('frame_gpu_bytes', 0) / 2**20:.0f} |")
PY
mv "$out/table.md.tmp" "$out/table.md"
cat "$out/table.md"

# The 8K profiles, and the work counters at every profile (docs/player/8k-panels.md).
if [ "${LFD_BENCH_8K:-1}" != 0 ]; then
  bash "$here/gpu-bench-8k.sh" "$bench" "$profiles" "$out" "$frames" "$warmup" "$deadline" "${packs[@]}"
fi

# --aniso 16 on the textured scenes (docs/player/reconstruction.md "Anisotropic filtering"): mvr
# against lfdpr with each of its filters (--lfdpr-aniso hardware, a GPU's default, and taps),
# lfdpr's EIA RMSE against mvr's (issue 23's target: 0.01). LFD_BENCH_ANISO=0 skips it.
if [ "${LFD_BENCH_ANISO:-1}" != 0 ] && [ "$SECONDS" -lt "$deadline" ]; then
  aniso=()
  for pack in "${packs[@]}"; do
    scene=$(basename "$pack" .lfdpack)
    case "$scene" in car|room|dense) continue ;; esac # untextured: --aniso changes nothing
    for filter in hardware taps; do
      echo "gpu-bench: $scene --aniso 16 --lfdpr-aniso $filter"
      "$bench" "$pack" --renderers mvr,lfdpr --reference mvr --frames "$frames" --warmup "$warmup" --views 48 \
        --view-size 480x360 --aniso 16 --lfdpr-aniso "$filter" --out "$out/aniso-$scene-$filter" --quiet \
        > "$out/aniso-$scene-$filter.txt"
      aniso+=("aniso-$scene-$filter")
    done
  done
  if [ "${#aniso[@]}" -gt 0 ]; then
    python3 - "$out" "${aniso[@]}" > "$out/aniso.md.tmp" <<'PY'
import json, os, sys
out, runs = sys.argv[1], sys.argv[2:]
print("| scene | --lfdpr-aniso | lfdpr EIA RMSE vs mvr | view RMSE vs mvr | mvr total ms | lfdpr total ms |")
print("|---|---|---|---|---|---|")
for run in runs:
    b = json.load(open(os.path.join(out, run, "bench.json")))
    r = {x["name"]: x for x in b["renderers"]}
    q = r["lfdpr"].get("quality", {})
    scene, flt = run[len("aniso-"):].rsplit("-", 1)
    total = lambda name: r[name]["stages"]["total"]["mean"]
    print(f"| {scene} | {flt} | {q.get('eia', {}).get('rmse', float('nan')):.3f} | "
          f"{q.get('all_views', {}).get('rmse', float('nan')):.3f} | {total('mvr'):.2f} | {total('lfdpr'):.2f} |")
PY
    mv "$out/aniso.md.tmp" "$out/aniso.md"
    cat "$out/aniso.md"
  fi
fi

# Image-based lighting's cost (docs/lighting.md "Cost"): the runs above light with the
# defaults (the neutral studio, PBR Neutral); each scene again with the fixed light and no
# tone mapper, mvr and lfdpr, and the added share per renderer. LFD_BENCH_LIGHTING=0 skips it.
if [ "${LFD_BENCH_LIGHTING:-1}" != 0 ] && [ "$SECONDS" -lt "$deadline" ]; then
  lighting=()
  for pack in "${packs[@]}"; do
    scene=$(basename "$pack" .lfdpack)
    [ "$scene" = dense ] && continue # its 1M triangles say nothing more about shading
    echo "gpu-bench: $scene --environment none --tone-map none"
    "$bench" "$pack" --renderers mvr,lfdpr --reference mvr --frames "$frames" --warmup "$warmup" --views 48 \
      --view-size 480x360 --environment none --tone-map none --out "$out/light-none-$scene" --quiet \
      > "$out/light-none-$scene.txt"
    lighting+=("$scene")
  done
  if [ "${#lighting[@]}" -gt 0 ]; then
    python3 - "$out" "${lighting[@]}" > "$out/lighting.md.tmp" <<'PY'
import json, os, sys
out, scenes = sys.argv[1], sys.argv[2:]
print("| scene | mvr ms: fixed light -> IBL | mvr added | lfdpr ms: fixed light -> IBL | lfdpr added |")
print("|---|---|---|---|---|")
for scene in scenes:
    def totals(run):
        b = json.load(open(os.path.join(out, run, "bench.json")))
        return {r["name"]: r["stages"]["total"]["mean"] for r in b["renderers"] if r.get("timed")}
    off, on = totals(f"light-none-{scene}"), totals(scene)
    cells = []
    for name in ("mvr", "lfdpr"):
        if name in off and name in on:
            cells += [f"{off[name]:.2f} -> {on[name]:.2f}", f"{100 * (on[name] / off[name] - 1):+.0f}%"]
        else:
            cells += ["-", "-"]
    print(f"| {scene} | " + " | ".join(cells) + " |")
PY
    mv "$out/lighting.md.tmp" "$out/lighting.md"
    cat "$out/lighting.md"
  fi
fi
