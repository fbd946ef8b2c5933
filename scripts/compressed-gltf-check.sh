#!/usr/bin/env bash
# Compressed glTF as pipelines ship it (docs/baker/gltf-extensions.md): each scene is converted
# with gltf-transform (draco, meshopt, webp, quantize), every variant is baked, and its
# still EIA (mvr, no turntable) is compared with the uncompressed scene's (SSIM, lfd-compare).
# Then the Draco variant's bake time is set against the uncompressed file's, in alternating
# runs (the ratio of the medians). Prints a Markdown table.
#
# Usage: bash scripts/compressed-gltf-check.sh OUTDIR [SCENE.gltf ...]   (from the source
# tree, after a full build; default scenes: the third-party ones in ../shared/scenes)
# Environment: GLTF_TRANSFORM (default: gltf-transform on PATH, else
# /opt/gltf-transform/node_modules/.bin/gltf-transform), LFD_TIMING_RUNS (default 5).
set -euo pipefail
out="$1"
shift
scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then
  for dir in ../shared/scenes/*/; do
    gltf=$(ls "$dir"*.gltf 2>/dev/null | head -n 1 || true)
    [ -n "$gltf" ] && scenes+=("$gltf")
  done
fi
gt=${GLTF_TRANSFORM:-$(command -v gltf-transform || echo /opt/gltf-transform/node_modules/.bin/gltf-transform)}
runs=${LFD_TIMING_RUNS:-5}
bake=./build/baker/lfd-bake
play=./build/player/lfd-play
compare=./build/player/metrics/lfd-compare
for tool in "$gt" "$bake" "$play" "$compare"; do
  [ -x "$tool" ] || { echo "compressed-gltf-check: $tool not found (build everything; install gltf-transform)" >&2; exit 1; }
done
mkdir -p "$out"

# The still EIA of a pack (mvr: the raster reference renderer).
eia() { "$play" "$1" --headless --renderer mvr --out "$2" --frames 1 --no-turntable >/dev/null 2>&1; }
ssim() { "$compare" --json "$1" "$2" | python3 -c 'import json,sys; print("%.5f" % json.load(sys.stdin)["ssim"])'; }
seconds() { local s; s=$(date +%s.%N); "$@" >/dev/null 2>&1; python3 -c "import sys; print(f'{$(date +%s.%N) - $s:.3f}')"; }
median() { python3 -c 'import statistics,sys; print("%.3f" % statistics.median(map(float, sys.argv[1:])))' "$@"; }

echo "| scene | draco SSIM | meshopt SSIM | webp SSIM | quantize SSIM | bake s (source) | bake s (draco) | draco / source |"
echo "|---|---|---|---|---|---|---|---|"
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" | sed 's/\.[^.]*$//')
  "$bake" "$scene" -o "$out/$name.lfdpack" --quiet 2>/dev/null
  eia "$out/$name.lfdpack" "$out/$name.png"
  row="| $name"
  for variant in draco meshopt webp quantize; do
    file="$out/$name-$variant.glb"
    "$gt" "$variant" "$scene" "$file" >/dev/null 2>&1
    "$bake" "$file" -o "$out/$name-$variant.lfdpack" --quiet 2>/dev/null
    eia "$out/$name-$variant.lfdpack" "$out/$name-$variant.png"
    row="$row | $(ssim "$out/$name.png" "$out/$name-$variant.png")"
  done
  # Paired timings: source and Draco alternate, so load on the machine hits both alike.
  plain=() draco=()
  for _ in $(seq "$runs"); do
    plain+=("$(seconds "$bake" "$scene" -o "$out/timing.lfdpack" --quiet)")
    draco+=("$(seconds "$bake" "$out/$name-draco.glb" -o "$out/timing.lfdpack" --quiet)")
  done
  p=$(median "${plain[@]}") d=$(median "${draco[@]}")
  echo "$row | $p | $d | $(python3 -c "print('%.2f' % ($d / $p))") |"
done
