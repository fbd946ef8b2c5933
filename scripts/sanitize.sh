#!/usr/bin/env bash
# The CPU test suites (formats, baker: every test that needs no OpenGL) built with
# AddressSanitizer + UndefinedBehaviorSanitizer in ./build-asan and run with CTest. Any
# sanitizer report aborts its test (-fno-sanitize-recover), so the run fails on it.
# The player (GL) is left out: its tests run on Mesa llvmpipe, whose JIT-compiled code
# and uninstrumented driver are outside what this build checks.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
# -O1: sanitizer reports keep usable stack traces, and the suites run faster than at -O0.
# -g1 (line tables): reports name file:line, which is all the symbolizer reads; full debug
# information made every object about a third slower to compile.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DLFD_WERROR=ON -DLFD_SANITIZE=ON -DLFD_BUILD_PLAYER=OFF >/dev/null
cmake --build build-asan -j "$jobs" >/dev/null
export ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
export LSAN_OPTIONS=suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0
status=0
(cd build-asan && ctest --output-on-failure -j "$jobs" --timeout 900 --output-junit ctest-junit.xml "$@") || status=$?
python3 scripts/ctest_summary.py build-asan/ctest-junit.xml build-asan/tests | sed 's/^tests:/sanitize:/'
exit "$status"
