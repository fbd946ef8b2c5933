#!/usr/bin/env bash
# Configures and builds ./build-asan: the one instrumented build that both the sanitizer
# suites (scripts/sanitize.sh) and the libFuzzer targets (scripts/fuzz.sh) use, so the
# formats and baker libraries are compiled once for both (issue 39: CI compiled them twice,
# once with GCC for the suites and once with clang for the fuzzers).
#
#   bash scripts/sanitized-build.sh [--target NAME ...]
#
# clang, AddressSanitizer + UndefinedBehaviorSanitizer (-fno-sanitize-recover: any report is
# fatal), and -fsanitize=fuzzer-no-link everywhere: the coverage libFuzzer steers by. The
# suites link without libFuzzer, where that coverage only calls the sanitizer runtime's empty
# callbacks. The player (GL) is left out: its tests run on Mesa llvmpipe, whose JIT-compiled
# code and uninstrumented driver are outside what this build checks.
# -O1 -g1 is what OSS-Fuzz builds with: reports keep usable stack traces, the suites run
# faster than at -O0, and line tables (-g1) are all the symbolizer reads (full debug
# information made every object about a third slower to compile). The test executables
# compile at -O0 (LFD_TEST_CXX_FLAGS): the sanitizers check the same, the work they test
# runs in the -O1 libraries, and an instrumented test file compiles about twice as fast
# (gltf_validation_test.cpp: 19.3 s at -Og, 8.5 s at -O0).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)

targets=()
while (($#)); do
  case $1 in
    --target)
      targets+=("$2")
      shift 2
      ;;
    *)
      echo "sanitized-build.sh: unknown argument $1 (only --target NAME)" >&2
      exit 2
      ;;
  esac
done

CC=clang CXX=clang++ cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DLFD_TEST_CXX_FLAGS="-O0;-g1" -DLFD_WERROR=ON -DLFD_UNITY_BUILD=ON -DLFD_SANITIZE=ON -DLFD_BUILD_FUZZERS=ON -DLFD_BUILD_PLAYER=OFF >/dev/null
cmake --build build-asan -j "$jobs" ${targets[@]+--target "${targets[@]}"} >/dev/null
