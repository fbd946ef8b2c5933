#!/usr/bin/env bash
# The whole test suite (what CI runs, via .ci/run), each step timed:
#   setup       install missing Debian packages (scripts/setup.sh)
#   build       configure and build ./build (scripts/build.sh)
#   ctest       every CTest test: CPU tests and GL tests on a headless EGL context (Mesa
#               llvmpipe where there is no GPU); prints how many tests ran per binary and
#               why each skipped test skipped
#   sanitize    the CPU suites built with ASan + UBSan in ./build-asan (scripts/sanitize.sh)
#   fuzz        the libFuzzer targets, LFD_FUZZ_SECONDS each (default 60) (scripts/fuzz.sh)
# Under CI=true a test whose prerequisite is missing (third-party scenes, headless GL,
# Xvfb) fails instead of skipping (tests/common/skip_or_fail.h).
# Every step after the build runs even if an earlier one failed; the exit status is
# non-zero if any failed.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)

failed=()
times=()
step() {
  local name=$1
  shift
  local start=$SECONDS
  echo "test.sh: -- $name"
  if "$@"; then
    times+=("$name $((SECONDS - start)) s")
  else
    times+=("$name $((SECONDS - start)) s (FAILED)")
    failed+=("$name")
  fi
}

run_ctest() {
  local status=0
  # The 16384^2 texture memory test is opt-in for local runs; here it runs (about 20 s,
  # 1.4 GiB peak). The sanitizer step leaves it skipped (ASan multiplies that memory).
  (cd build && LFD_BIG_TEXTURE_TEST=1 ctest --output-on-failure -j "$jobs" --timeout 900 \
    --output-junit ctest-junit.xml) || status=$?
  python3 scripts/ctest_summary.py build/ctest-junit.xml build/tests
  return "$status"
}

step setup bash scripts/setup.sh
step build bash scripts/build.sh
if ((${#failed[@]} == 0)); then
  step ctest run_ctest
  step sanitize bash scripts/sanitize.sh
  step fuzz bash scripts/fuzz.sh
fi

echo "test.sh: step times: $(IFS=,; echo "${times[*]}" | sed 's/,/, /g'); total ${SECONDS} s"
if ((${#failed[@]})); then
  echo "test.sh: FAILED: ${failed[*]}"
  exit 1
fi
echo "test.sh: all steps passed"
