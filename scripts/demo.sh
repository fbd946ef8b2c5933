#!/usr/bin/env bash
# The main job on the bundled sample: install dependencies, build, generate the project's
# own "car" sample scene, bake it for the paper's prototype display and render an EIA and
# a quilt headless (48 views of 480x360, EIA at 3840x2160). Outputs go to ./out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
mkdir -p out
./build/samples/lfd-make-samples out/samples --scene car
./build/baker/lfd-bake out/samples/car/car.gltf -o out/car.lfdpack
if [ -x ./build/player/lfd-play ]; then
  ./build/player/lfd-play out/car.lfdpack --headless --out out/car_eia.png --quilt out/car_quilt.png \
    --stats out/car_stats.json
  echo "demo: wrote out/car_eia.png, the quilt and out/car_stats.json"
fi
