#!/usr/bin/env bash
# Batch baking end to end (docs/baker/batch-baking.md): install the toolkit into a temporary
# prefix, configure samples/batch_bake over two generated scenes with every generator
# available (Ninja, Unix Makefiles), and check that a clean build bakes both packs, a
# rebuild bakes nothing, touching one texture rebakes only the pack that read it, and the
# packs verify. Usage: batch_bake_test.sh SOURCE_DIR BUILD_DIR [TOOL,TOOL,...]
# (the tools the install must hold; default every tool).
set -euo pipefail
src=$1 build=$2
IFS=, read -r -a tools <<<"${3:-lfd-bake,lfd-make-samples,lfd-play,lfd-bench,lfd-compare}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "batch_bake_test: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$work/prefix" >/dev/null
for tool in "${tools[@]}"; do
  [ -x "$work/prefix/bin/$tool" ] || fail "$tool not installed"
  PATH="$work/prefix/bin:$PATH" $tool --help >/dev/null || fail "installed $tool --help failed"
done
[ -f "$work/prefix/share/doc/lfdpr/README.md" ] || fail "README not installed"
[ -f "$work/prefix/share/lfd/lfd_blender.zip" ] || fail "Blender add-on zip not installed"
"$work/prefix/bin/lfd-make-samples" "$work/assets" --scene gallery --texture-size 64 --quiet
"$work/prefix/bin/lfd-make-samples" "$work/assets" --scene car --quiet
profile="$work/prefix/share/lfd/profiles/looking_glass_portrait_visual.json"
[ -f "$profile" ] || fail "display profiles not installed"

generators=("Unix Makefiles")
command -v ninja >/dev/null && generators=("Ninja" "${generators[@]}")
for generator in "${generators[@]}"; do
  b="$work/build-${generator// /_}"
  cmake -S "$src/samples/batch_bake" -B "$b" -G "$generator" -DCMAKE_PREFIX_PATH="$work/prefix" \
        -DLFD_ASSET_DIR="$work/assets" -DLFD_DISPLAY="$profile" -DLFD_BAKE_OPTIONS="--threads;1" >/dev/null
  log="$work/log"
  cmake --build "$b" >"$log" 2>&1 || { cat "$log"; fail "$generator: clean build failed"; }
  for pack in gallery car; do
    [ -f "$b/packs/$pack.lfdpack" ] || fail "$generator: $pack.lfdpack not baked"
    grep -q "$profile" "$b/packs/$pack.lfdpack.d" || fail "$generator: $pack's depfile lacks the profile"
  done
  grep -q "picture.png" "$b/packs/gallery.lfdpack.d" || fail "$generator: gallery's depfile lacks its images"
  cmake --build "$b" >"$log" 2>&1
  if grep -q "lfd-bake " "$log"; then cat "$log"; fail "$generator: a rebuild with nothing changed baked again"; fi
  sleep 1 # coarse file times: the touch must be newer than the packs
  touch "$work/assets/gallery/picture.png"
  cmake --build "$b" >"$log" 2>&1
  grep -q "lfd-bake gallery.lfdpack" "$log" || { cat "$log"; fail "$generator: touching picture.png did not rebake gallery"; }
  if grep -q "lfd-bake car.lfdpack" "$log"; then cat "$log"; fail "$generator: touching gallery's image rebaked car"; fi
  "$work/prefix/bin/lfd-bake" --inspect "$b/packs/gallery.lfdpack" >/dev/null || fail "$generator: gallery pack does not verify"
  echo "$generator: clean build, no-op rebuild and one touched image behave"
done
