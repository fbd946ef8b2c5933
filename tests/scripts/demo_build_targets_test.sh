#!/usr/bin/env bash
# scripts/demo.sh builds only the tools it runs (issue 42: building the test suites made
# the first command take 587 s on two cores): its scripts/build.sh line names --target for
# exactly the tools the script runs from ./build, build.sh turns them into one
# `cmake --build ... --target` (and builds everything without --target, for test.sh), and
# in a Ninja build tree those targets need fewer compile commands than the whole build.
#   demo_build_targets_test.sh SOURCE_DIR [BINARY_DIR]
set -euo pipefail
src=$1
bin=${2:-}
fail() { echo "FAIL: $*" >&2; exit 1; }

demo=$src/scripts/demo.sh
build_line=$(grep -E '^[^#]*scripts/build\.sh' "$demo") || fail "demo.sh has no scripts/build.sh line"
[[ $(grep -cE '^[^#]*scripts/build\.sh' "$demo") == 1 ]] || fail "demo.sh runs build.sh more than once"
# The targets named on the build line, and the tools the script runs from ./build.
named=$(grep -oE -- '--target[ =][A-Za-z0-9_.-]+' <<<"$build_line" | sed -E 's/--target[ =]//' | sort -u || true)
run=$(grep -oE '\./build/[A-Za-z0-9_/.-]*/(lfd-[a-z-]+)' "$demo" | sed -E 's|.*/||' | sort -u)
[[ -n $named ]] || fail "demo.sh's build line names no --target (it would build every test suite): $build_line"
[[ -n $run ]] || fail "found no ./build/.../lfd-* tool run by demo.sh"
[[ $named == "$run" ]] || fail "demo.sh builds {$(echo $named)} but runs {$(echo $run)}"
echo "demo.sh builds and runs: $(echo $named)"

# build.sh: the --target names reach `cmake --build`, other arguments the configure step.
targets=()
for t in $named; do targets+=(--target "$t"); done
out=$(LFD_BUILD_DRY_RUN=1 bash "$src/scripts/build.sh" "${targets[@]}" -DLFD_EXAMPLE=ON)
grep -qE "^cmake --build build -j [0-9]+ --target $(echo $named)\$" <<<"$out" || fail "build.sh with targets: $out"
grep -qE '^cmake -S \. -B build .*-DLFD_EXAMPLE=ON$' <<<"$out" || fail "build.sh configure args: $out"
out=$(LFD_BUILD_DRY_RUN=1 bash "$src/scripts/build.sh")
grep -qE '^cmake --build build -j [0-9]+$' <<<"$out" || fail "build.sh without targets must build everything: $out"
if bash "$src/scripts/build.sh" --target 2>/dev/null; then fail "build.sh accepted --target without a name"; fi

# In a Ninja build tree: the targets exist, and need fewer compile commands than all.
if [[ -n $bin && -f $bin/build.ninja ]] && command -v ninja >/dev/null; then
  for t in $named; do
    ninja -C "$bin" -t query "$t" >/dev/null 2>&1 || fail "no target $t in $bin"
  done
  compiles() { ninja -C "$bin" -t commands "$@" | grep -cE ' -c .*\.(cpp|cc|c|cxx)( |$)' || true; }
  demo_units=$(compiles $named)
  all_units=$(compiles)
  echo "compile units: demo targets $demo_units, everything $all_units"
  ((demo_units > 0 && demo_units < all_units)) || fail "demo targets compile $demo_units of $all_units units"
fi
echo "PASS"
