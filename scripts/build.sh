#!/usr/bin/env bash
# Configures and builds the project into ./build (Release with debug info, warnings on).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLFD_WERROR=ON "$@" >/dev/null
cmake --build build -j "$jobs"
