#!/usr/bin/env bash
# The main job on the bundled sample: install dependencies, build, generate the project's
# own "car" sample scene, bake it for the paper's prototype display and render it headless
# (48 views of 480x360, EIA at 3840x2160) with LFDPR, plus the raster baseline (mvr) for
# comparison. Outputs go to ./out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
mkdir -p out
./build/samples/lfd-make-samples out/samples --scene car
./build/baker/lfd-bake out/samples/car/car.gltf -o out/car.lfdpack
# The paper's method (LFDPR) and the raster baseline render the same 48 views.
./build/player/lfd-play out/car.lfdpack --headless --renderer lfdpr --out out/car_eia.png \
  --quilt out/car_quilt.png --viewer-out out/car_viewer.png --stats out/car_stats.json
./build/player/lfd-play out/car.lfdpack --headless --renderer mvr --out out/car_eia_mvr.png \
  --stats out/car_stats_mvr.json
echo "demo: wrote out/car_eia.png (lfdpr), out/car_eia_mvr.png (mvr), the quilt, a simulated viewer image and stats"
