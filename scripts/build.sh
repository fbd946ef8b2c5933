#!/usr/bin/env bash
# Configures and builds the project into ./build (Release with debug info, warnings on, and a
# unity build: each target's sources compile in batches, CMakeLists.txt LFD_UNITY_BUILD).
#
#   bash scripts/build.sh [--target NAME ...] [CMAKE_CONFIGURE_ARGS ...]
#
# Without --target it builds everything (what scripts/test.sh needs: every test suite).
# With one or more --target NAME it builds only those targets and what they depend on:
# scripts/demo.sh builds just the four tools it runs, not the test suites, which are most
# of a fresh build's compile units (issue 42: the demo took 587 s on two cores, mostly
# compiling tests it never runs). Every other argument goes to the cmake configure step.
# LFD_BUILD_DRY_RUN=1 prints the two commands instead of running them (tested by
# tests/scripts/demo_build_targets_test.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)

targets=()
configure=()
while (($#)); do
  case $1 in
    --target)
      if (($# < 2)) || [[ -z $2 || $2 == -* ]]; then
        echo "build.sh: --target needs a target name (e.g. --target lfd-play)" >&2
        exit 2
      fi
      targets+=("$2")
      shift 2
      ;;
    --target=*)
      targets+=("${1#--target=}")
      shift
      ;;
    *)
      configure+=("$1")
      shift
      ;;
  esac
done

configure_cmd=(cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLFD_WERROR=ON -DLFD_UNITY_BUILD=ON ${configure[@]+"${configure[@]}"})
build_cmd=(cmake --build build -j "$jobs")
if ((${#targets[@]})); then
  build_cmd+=(--target "${targets[@]}")
fi

if [[ ${LFD_BUILD_DRY_RUN:-0} == 1 ]]; then
  echo "${configure_cmd[*]}"
  echo "${build_cmd[*]}"
  exit 0
fi
"${configure_cmd[@]}" >/dev/null
"${build_cmd[@]}"
