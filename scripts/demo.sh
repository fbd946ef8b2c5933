#!/usr/bin/env bash
# The main job on the bundled sample: install dependencies, build, generate the project's
# own "car" sample scene, bake it for the paper's prototype display and render it headless
# (48 views of 480x360, EIA at 3840x2160) with LFDPR, plus the raster baseline (mvr) for
# comparison, then a short warmed-up comparison of the two (one frame of a cold run says
# more about start-up than about either method). Outputs go to ./out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# Only the tools this script runs (the test suites are most of a fresh build; scripts/test.sh
# builds everything).
bash scripts/build.sh --target lfd-make-samples --target lfd-bake --target lfd-play --target lfd-bench
mkdir -p out
./build/samples/lfd-make-samples out/samples --scene car
./build/baker/lfd-bake out/samples/car/car.gltf -o out/car.lfdpack
# The paper's method (LFDPR) and the raster baseline render the same 48 views.
./build/player/lfd-play out/car.lfdpack --headless --renderer lfdpr --out out/car_eia.png \
  --quilt out/car_quilt.png --viewer-out out/car_viewer.png --stats out/car_stats.json
./build/player/lfd-play out/car.lfdpack --headless --renderer mvr --out out/car_eia_mvr.png \
  --stats out/car_stats_mvr.json
echo "demo: wrote out/car_eia.png (lfdpr), out/car_eia_mvr.png (mvr), the quilt, a simulated viewer image and stats"
# The frames above are cold (shader compilation, first uploads). Warmed up, the methods
# take turns frame by frame: 2 untimed + 5 timed frames each, EIA compared with mvr's.
./build/player/lfd-bench out/car.lfdpack --renderers mvr,lfdpr --warmup 2 --frames 5 --reference mvr \
  --out out/car_bench --quiet
python3 - out/car_bench/results.json <<'PY'
import json, sys
run = json.load(open(sys.argv[1]))["runs"][0]
ms = {r["name"]: r["total_ms"] for r in run["renderers"]}
ssim = next(r["quality"]["eia"]["ssim"] for r in run["renderers"] if r["name"] == "lfdpr")
print(f"demo: warmed up, {run['profile']['views']} views of {run['profile']['view_width']}x"
      f"{run['profile']['view_height']}: lfdpr {ms['lfdpr']:.1f} ms, mvr {ms['mvr']:.1f} ms per frame "
      f"(lfdpr {ms['mvr'] / ms['lfdpr']:.2f}x mvr's speed), EIA SSIM lfdpr vs mvr {ssim:.4f}")
PY
echo "demo: the full comparison (every renderer, error against the gold standard, charts) is docs/bench/lfd-bench.md (scripts/bench-matrix.sh)"
