#!/usr/bin/env bash
# Writes the compressed glTF fixtures of tests/baker/import/gltf_compression_test.cpp from the
# project's own gallery sample (32-pixel textures), the way pipelines ship files:
#   gallery.glb           the sample as one GLB (gltf-transform copy): the reference
#   gallery-draco.glb     KHR_draco_mesh_compression (gltf-transform draco)
#   gallery-meshopt.glb   EXT_meshopt_compression + KHR_mesh_quantization (gltf-transform meshopt)
#   gallery-webp.glb      EXT_texture_webp, required (gltf-transform webp)
#   gallery-quantize.glb  KHR_mesh_quantization (gltf-transform quantize)
# Usage (from the source tree, after building lfd-make-samples; needs gltf-transform 4.5,
# npm @gltf-transform/cli): bash tests/data/gltf_compressed/make_fixtures.sh
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
gt=${GLTF_TRANSFORM:-$(command -v gltf-transform || echo /opt/gltf-transform/node_modules/.bin/gltf-transform)}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
./build/samples/lfd-make-samples "$tmp" --scene gallery --texture-size 32 --quiet
"$gt" copy "$tmp/gallery/gallery.gltf" "$here/gallery.glb"
for variant in draco meshopt webp quantize; do
  "$gt" "$variant" "$tmp/gallery/gallery.gltf" "$here/gallery-$variant.glb"
done
