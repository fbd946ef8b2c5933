#!/usr/bin/env bash
# The whole test suite: install dependencies, build, run every CTest test (CPU tests and
# GL tests on a headless EGL context - Mesa llvmpipe where there is no GPU).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
cd build
ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" --timeout 900
