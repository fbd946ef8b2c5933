#!/usr/bin/env bash
# The LFDPR bench table on a GPU machine (or any machine): builds, generates the samples
# (car, gallery, room, and the paper-scale dense block), bakes them and the third-party
# scenes in ../shared/scenes when present, and runs lfd-bench at the prototype's 48 views
# of 480x360 for mvr, mvr-layered, lfdpr (visibility pipeline) and lfdpr-paper.
# Results: out/gpu-bench/<scene>/bench.{json,csv} and a summary table in
# out/gpu-bench/table.md. Usage: bash scripts/gpu-bench.sh [FRAMES (default 20)]
set -euo pipefail
cd "$(dirname "$0")/.."
frames="${1:-20}"
[ -x build/player/lfd-bench ] || bash scripts/build.sh
out=out/gpu-bench
mkdir -p "$out/packs"
./build/samples/lfd-make-samples "$out/samples" --scene all --quiet
./build/samples/lfd-make-samples "$out/samples" --scene dense --quiet
scenes=()
for s in car gallery room dense; do
  ./build/baker/lfd-bake "$out/samples/$s/$s.gltf" -o "$out/packs/$s.lfdpack" --quiet
  scenes+=("$s")
done
if [ -d ../shared/scenes ]; then
  for dir in ../shared/scenes/*/; do
    name=$(basename "$dir")
    gltf=$(ls "$dir"*.gltf 2>/dev/null | head -n 1 || true)
    [ -n "$gltf" ] || continue
    ./build/baker/lfd-bake "$gltf" -o "$out/packs/$name.lfdpack" --quiet
    scenes+=("$name")
  done
fi
table="$out/table.md"
{
  echo "| scene | renderer | point gen ms (points) | view gen ms | resolve ms | EIA ms | total ms | vs mvr | vs mvr-layered | EIA RMSE | EIA SSIM |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
} > "$table.tmp"
for s in "${scenes[@]}"; do
  echo "gpu-bench: $s"
  ./build/player/lfd-bench "$out/packs/$s.lfdpack" --renderers mvr,mvr-layered,lfdpr,lfdpr-paper \
    --reference mvr --frames "$frames" --warmup 3 --out "$out/$s" --quiet
  python3 - "$out/$s/bench.json" "$s" >> "$table.tmp" <<'PY'
import json, sys
b = json.load(open(sys.argv[1]))
def ms(r, stage):
    st = r.get("stages", {}).get(stage)
    return st["mean"] if st else None
rows = b["renderers"]
totals = {r["name"]: ms(r, "total") for r in rows}
for r in rows:
    f = lambda v: "-" if v is None else f"{v:.2f}"
    t = totals[r["name"]]
    pts = r.get("points")
    pg = ms(r, "point_generation")
    pgs = "-" if pg is None else f"{pg:.2f} ({pts/1e6:.2f}M)" if pts else f"{pg:.2f}"
    q = r.get("quality", {}).get("eia", {})
    vs = lambda other: "-" if not totals.get(other) or not t else f"{totals[other]/t:.2f}x"
    print(f"| {sys.argv[2]} | {r['name']} | {pgs} | {f(ms(r,'view_generation'))} | {f(ms(r,'resolve'))} | "
          f"{f(ms(r,'eia'))} | {f(t)} | {vs('mvr')} | {vs('mvr-layered')} | "
          f"{f(q.get('rmse'))} | {('-' if q.get('ssim') is None else format(q['ssim'], '.4f'))} |")
PY
done
mv "$table.tmp" "$table"
cat "$table"
