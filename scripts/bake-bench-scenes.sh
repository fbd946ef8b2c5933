#!/usr/bin/env bash
# The bench scenes, baked: generates the samples (car, gallery, room and the ~1.1M-triangle
# dense block) and bakes them and the third-party scenes of ../shared/scenes when present.
# Prints one pack path per line. Shared by bench-matrix.sh and gpu-bench.sh (tree mode).
# Usage: bash scripts/bake-bench-scenes.sh OUTDIR   (run from the source tree, after a build)
set -euo pipefail
out="$1"
mkdir -p "$out/packs"
./build/samples/lfd-make-samples "$out/samples" --scene all --quiet >&2
./build/samples/lfd-make-samples "$out/samples" --scene dense --quiet >&2
for s in car gallery room dense; do
  ./build/baker/lfd-bake "$out/samples/$s/$s.gltf" -o "$out/packs/$s.lfdpack" --quiet >&2
  echo "$out/packs/$s.lfdpack"
done
if [ -d ../shared/scenes ]; then
  for dir in ../shared/scenes/*/; do
    name=$(basename "$dir")
    gltf=$(ls "$dir"*.gltf "$dir"*.glb 2>/dev/null | head -n 1 || true)
    [ -n "$gltf" ] || continue
    ./build/baker/lfd-bake "$gltf" -o "$out/packs/$name.lfdpack" --quiet >&2
    echo "$out/packs/$name.lfdpack"
  done
fi
