#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, AddressSanitizer + UndefinedBehaviorSanitizer) in
# ./build-asan, the instrumented build the sanitizer suites use (scripts/sanitized-build.sh;
# after scripts/sanitize.sh there is nothing left to compile), and runs each for a bounded
# time:
#   lfd_pack_fuzz  the pack reader (tests/fuzz/pack_fuzz.cpp)
#   lfd_gltf_fuzz  glTF ingestion: import -> bounds -> tessellation -> triangle statistics
# Seeds: the project's samples (as self-contained .gltf and as baked packs), tests/data (with
# the Draco, meshopt, WebP and quantized GLBs of tests/data/gltf_compressed) and
# the broken-file corpus of Debian's assimp-testmodels. Fails on any finding (crash,
# sanitizer report, leak, timeout, out-of-memory); the input is kept in
# build-asan/findings/ - commit it under tests/data/fuzz/ as a regression test.
#
# Environment: LFD_FUZZ_SECONDS (per target, default 60; the two targets run side by side
# where there are two cores or more).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${LFD_FUZZ_SECONDS:-60}
build=build-asan

bash scripts/sanitized-build.sh --target lfd_pack_fuzz --target lfd_gltf_fuzz --target lfd-make-samples \
  --target lfd-bake

# ---- Seed corpora (rebuilt every run; the corpora libFuzzer grows stay in $build) ----
seeds=$build/seeds
rm -rf "$seeds" "$build/findings"
mkdir -p "$seeds/gltf" "$seeds/pack" "$build/corpus/gltf" "$build/corpus/pack" "$build/findings"
# The fuzzers have sanitizers on; the seed tools need not be fast, only correct.
export ASAN_OPTIONS=detect_leaks=0
"$build/samples/lfd-make-samples" "$seeds/samples" --scene all --texture-size 64 --instances 2 --quiet
# The skinned samples: packs with every deformation section (ACHN version 2 included).
"$build/samples/lfd-make-samples" "$seeds/samples" --scene character --quiet
"$build/samples/lfd-make-samples" "$seeds/samples" --scene crowd --instances 2 --quiet
for scene in "$seeds"/samples/*/*.gltf; do
  name=$(basename "$scene" .gltf)
  "$build/baker/lfd-bake" "$scene" -o "$seeds/pack/$name.lfdpack" --max-texture-size 64 --quiet
  # Self-contained copy (buffers and images as data URIs): the fuzzer writes one file.
  python3 - "$scene" "$seeds/gltf/sample_$name.gltf" <<'EOF'
import base64, json, os, sys
src, dst = sys.argv[1], sys.argv[2]
doc = json.load(open(src))
base = os.path.dirname(src)
for key, mime in (("buffers", "application/octet-stream"), ("images", "image/png")):
    for item in doc.get(key, []):
        if "uri" in item and not item["uri"].startswith("data:"):
            data = open(os.path.join(base, item["uri"]), "rb").read()
            item["uri"] = "data:%s;base64,%s" % (mime, base64.b64encode(data).decode())
json.dump(doc, open(dst, "w"), separators=(",", ":"))
EOF
done
# The golden packs: every section of each format version, MEXT and LGHT included.
cp tests/data/golden_*.lfdpack "$seeds/pack/"
cp tests/data/gltf/*.gltf "$seeds/gltf/"
# Compressed geometry and textures: Draco, meshopt, WebP and quantized GLBs (tests/data/gltf_compressed).
cp tests/data/gltf_compressed/*.glb "$seeds/gltf/"
[ -d tests/data/fuzz/gltf ] && cp tests/data/fuzz/gltf/* "$seeds/gltf/"
[ -d tests/data/fuzz/pack ] && cp tests/data/fuzz/pack/* "$seeds/pack/"
assimp=/usr/share/assimp/models/glTF2
if [ -d "$assimp" ]; then
  find "$assimp" \( -name '*.gltf' -o -name '*.glb' \) -size -256k | while read -r f; do
    cp "$f" "$seeds/gltf/assimp_$(echo "${f#"$assimp"/}" | tr '/' '_')"
  done
fi
unset ASAN_OPTIONS

# ---- Runs --------------------------------------------------------------------------
export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=0
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
# One target per core at once where there are two (CI's two cores): each still runs for
# $seconds, as many executions as alone, and the step takes half the time.
jobs=$(nproc 2>/dev/null || echo 1)
run_target() {
  local target=$1 log=$build/fuzz_$1.log start result
  start=$(date +%s)
  if "$build/tests/fuzz/lfd_${target}_fuzz" "$build/corpus/$target" "$seeds/$target" \
      -max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 -malloc_limit_mb=1024 -max_len=262144 \
      -print_final_stats=1 -artifact_prefix="$build/findings/$target-" >"$log" 2>&1; then
    result=ok
  else
    result=FAILED
  fi
  echo "$result $(( $(date +%s) - start ))" >"$build/fuzz_$target.result"
}
targets=(pack gltf)
for target in "${targets[@]}"; do
  rm -f "$build/fuzz_$target.result"
  if ((jobs >= 2)); then
    run_target "$target" &
  else
    run_target "$target"
  fi
done
wait
status=0
for target in "${targets[@]}"; do
  log=$build/fuzz_$target.log
  read -r result elapsed <"$build/fuzz_$target.result" || { result=FAILED; elapsed=?; }
  [ "$result" = ok ] || status=1
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  echo "fuzz: $target: ${runs:-?} executions in $elapsed s, corpus $(ls "$build/corpus/$target" | wc -l) files: $result"
  if [ "$result" != ok ]; then
    grep -E "ERROR|SUMMARY|==[0-9]+==|runtime error|Test unit written" "$log" | head -20
    echo "fuzz: full log in $log; reproduce with $build/tests/fuzz/lfd_${target}_fuzz FILE"
  fi
done
exit "$status"
