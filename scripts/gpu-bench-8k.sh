#!/usr/bin/env bash
# The 8K part of gpu-bench.sh (docs/player/8k-panels.md "gpu-bench at 8K"): lfd-bench on
# every pack at the 32" and 65" Looking Glass class 8K profiles, each at the vendor quilt's
# view size and at the panel-matched size (N * w * h = W * H), mvr against lfdpr, timed
# without the work counters; then one counted frame of lfdpr per run
# (--lfdpr-work-counters) for the work table. Writes OUTDIR/8k/<run>/bench.{json,csv},
# OUTDIR/8k/<run>-work/bench.json and the tables OUTDIR/8k.md (times) and OUTDIR/8k-work.md
# (work counters).
#
# Usage: bash gpu-bench-8k.sh LFD_BENCH PROFILE_DIR OUTDIR FRAMES WARMUP DEADLINE PACK...
# DEADLINE: the shell's $SECONDS past which no further run starts (gpu-bench.sh keeps the
# whole call under its budget); runs left out are listed in OUTDIR/8k.md.
# LFD_BENCH_8K_PROFILES: the profiles to run, in order (default "p0 65m 65q 32m 32q"):
#   p0  48 x 480x360, the prototype: the counted frame only (gpu-bench.sh timed it already)
#   65m 72 x 960x480 (65", panel-matched)   65q 72 x 1024x910 (65" vendor quilt)
#   32m 48 x 960x720 (32", panel-matched)   32q 49 x 1170x1170 (32" vendor quilt)
# LFD_BENCH_8K_RENDERERS (default mvr,lfdpr,lfdpr-no-margin-trim: the margin trim's effect
# where point-views cost most, never timed on a GPU yet); LFD_BENCH_8K_COUNTERS=0 skips the
# counted frames.
set -euo pipefail
bench=$1 profiles=$2 out=$3 frames=$4 warmup=$5 deadline=$6
shift 6
renderers="${LFD_BENCH_8K_RENDERERS:-mvr,lfdpr,lfdpr-no-margin-trim}"
mkdir -p "$out/8k"
skipped=()
runs=()

# A profile's lfd-bench arguments.
profile_args() {
  case "$1" in
    p0) echo "--views 48 --view-size 480x360" ;;
    65m) echo "--display $profiles/looking_glass_65_8k.json --views 72 --view-size 960x480" ;;
    65q) echo "--display $profiles/looking_glass_65_8k.json" ;;
    32m) echo "--display $profiles/looking_glass_32_8k.json --views 48 --view-size 960x720" ;;
    32q) echo "--display $profiles/looking_glass_32_8k.json" ;;
    *) echo "gpu-bench-8k: unknown profile $1 (65m, 65q, 32m or 32q)" >&2; return 2 ;;
  esac
}

for profile in ${LFD_BENCH_8K_PROFILES:-p0 65m 65q 32m 32q}; do
  args=$(profile_args "$profile")
  for pack in "$@"; do
    name="$(basename "$pack" .lfdpack)-$profile"
    if [ "$SECONDS" -ge "$deadline" ]; then
      skipped+=("$name")
      continue
    fi
    echo "gpu-bench: 8K $name ($args)"
    if [ "$profile" != p0 ]; then
      # shellcheck disable=SC2086 # args is a list of words
      "$bench" "$pack" $args --renderers "$renderers" --reference mvr --frames "$frames" --warmup "$warmup" \
        --lens-positions 1 --out "$out/8k/$name" --quiet > "$out/8k/$name.txt"
    fi
    if [ "${LFD_BENCH_8K_COUNTERS:-1}" != 0 ]; then
      # shellcheck disable=SC2086
      "$bench" "$pack" $args --renderers lfdpr --reference lfdpr --frames 1 --warmup 1 --lens-positions 1 \
        --lfdpr-work-counters --out "$out/8k/$name-work" --quiet > "$out/8k/$name-work.txt"
    fi
    runs+=("$name")
  done
done

[ "${#runs[@]}" -gt 0 ] || { echo "gpu-bench-8k: no run fitted in the budget" >&2; exit 0; }
python3 "$(dirname "${BASH_SOURCE[0]}")/gpu_bench_8k_tables.py" "$out" "${runs[@]}" -- "${skipped[@]}"
