#!/usr/bin/env bash
# The CPU test suites (formats, baker: every test that needs no OpenGL) built with
# AddressSanitizer + UndefinedBehaviorSanitizer in ./build-asan (scripts/sanitized-build.sh,
# shared with the fuzzers) and run with CTest. Any sanitizer report aborts its test
# (-fno-sanitize-recover), so the run fails on it.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
bash scripts/sanitized-build.sh
export ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
export LSAN_OPTIONS=suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0
# Left to the main step: the third-party scenes baked three times over for byte identity
# across thread counts (49 s instrumented, the longest test here). The instrumented run
# still bakes those scenes (BakeCli.BakesThirdPartyScenes) and the thread paths (the
# gallery, car and room packs for 1, 2 and 3 threads); the main step checks the identity.
outside=BakeThreadsCli.ThirdPartyPacksAreByteIdenticalForOneTwoAndThreeThreads
status=0
(cd build-asan && ctest --output-on-failure -j "$jobs" --timeout 900 --output-junit ctest-junit.xml -E "$outside" "$@") ||
  status=$?
python3 scripts/ctest_summary.py build-asan/ctest-junit.xml build-asan/tests | sed 's/^tests:/sanitize:/'
exit "$status"
