#!/usr/bin/env bash
# Makes a self-contained player bundle: a folder (and OUTDIR.tar.gz beside it) that runs
# lfd-play and lfd-bench on another Linux x86-64 machine that has a GL driver and nothing
# else (a display PC, a GPU server): docs/player/another-machine.md.
#
#   bash scripts/bundle-player.sh OUTDIR [PACK...]
#
# OUTDIR/
#   lfd-play, lfd-bench       launchers: set the library path and run the tools
#   gpu-bench.sh              the LFDPR bench table over packs/ (scripts/gpu-bench.sh), with
#                             gpu-bench-8k.sh, gpu_bench_8k_tables.py and profiles/ (the 8K ones)
#   libexec/                  the tools, stripped
#   lib/                      every shared library they need beyond glibc and the GL driver
#   lib/glvnd/                the GL vendor-neutral loaders (libEGL, libGL, libOpenGL,
#                             libGLdispatch, libGLX), used only where the machine has none
#   packs/                    the packs given (prebuilt: the target needs no baker)
#   bench_chart.py            lfd-bench's matrix chart (needs python3 with matplotlib there)
#   MANIFEST.txt              what is inside, the build's commit, the glibc it needs
# The tools need glibc 2.34 or later on the target (Debian 12, Ubuntu 22.04 and later).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 1 ]; then
  echo "usage: bash scripts/bundle-player.sh OUTDIR [PACK...]" >&2
  exit 2
fi
out=$1
shift
for pack in "$@"; do
  [ -f "$pack" ] || { echo "bundle-player: $pack: no such pack file" >&2; exit 2; }
done
# The build to bundle: ./build (made if missing), or LFD_BUILD_DIR.
build="${LFD_BUILD_DIR:-build}"
if [ -z "${LFD_BUILD_DIR:-}" ]; then
  [ -x build/player/lfd-play ] && [ -x build/player/lfd-bench ] || bash scripts/build.sh
fi
for tool in lfd-play lfd-bench; do
  [ -x "$build/player/$tool" ] || { echo "bundle-player: $build/player/$tool is missing (build first)" >&2; exit 1; }
done

# Step 1: a fresh folder, written beside the target and moved into place at the end, so an
# interrupted run never leaves a half bundle.
tmp="${out%/}.tmp-$$"
rm -rf "$tmp"
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/libexec" "$tmp/lib/glvnd" "$tmp/packs"

# Step 2: the tools, stripped (their shaders are embedded).
for tool in lfd-play lfd-bench; do
  strip --strip-unneeded -o "$tmp/libexec/$tool" "$build/player/$tool"
done

# Step 3: their shared libraries, except glibc's own (the target's must be used) and the
# GL loaders (the target's driver provides them; copies go to lib/glvnd for machines that
# have a driver but no loader).
skip='^(linux-vdso|ld-linux|libc\.so|libm\.so|libdl\.so|libpthread\.so|librt\.so|libresolv\.so|libEGL|libGL|libOpenGL|libGLX|libGLdispatch)'
for tool in lfd-play lfd-bench; do
  ldd "$build/player/$tool" | awk '/=> \//{print $1, $3}'
done | sort -u | while read -r name path; do
  if [[ "$name" =~ $skip ]]; then continue; fi
  cp -L "$path" "$tmp/lib/$name"
done
for name in libEGL.so.1 libGL.so.1 libOpenGL.so.0 libGLdispatch.so.0 libGLX.so.0; do
  # awk reads to the end: exiting at the first match could kill ldconfig with SIGPIPE, and
  # under pipefail that fails the assignment (exit 141) whenever ldconfig was still writing.
  path=$(ldconfig -p | awk -v n="$name" '$1 == n && /x86-64/ && !found {print $NF; found = 1}')
  [ -n "$path" ] && cp -L "$path" "$tmp/lib/glvnd/$name"
done

# Step 4: launchers. The library path holds only the bundle's folder; the GL loaders of
# lib/glvnd are added only where the machine lacks libEGL.so.1, and an NVIDIA driver
# installed outside /usr/share/glvnd (container images mount it at /usr/local/nvidia) is
# pointed to.
for tool in lfd-play lfd-bench; do
  cat > "$tmp/$tool" <<EOF
#!/usr/bin/env bash
# $tool from a self-contained bundle (scripts/bundle-player.sh).
here=\$(cd "\$(dirname "\${BASH_SOURCE[0]}")" && pwd)
libs="\$here/lib"
if ! ldconfig -p 2>/dev/null | grep -q 'libEGL\.so\.1 '; then
  libs="\$libs:\$here/lib/glvnd"
fi
if [ -z "\${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ] && ! ls /usr/share/glvnd/egl_vendor.d/*.json >/dev/null 2>&1; then
  for f in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json /etc/glvnd/egl_vendor.d/10_nvidia.json; do
    [ -f "\$f" ] && { export __EGL_VENDOR_LIBRARY_FILENAMES="\$f"; break; }
  done
fi
export LD_LIBRARY_PATH="\$libs\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}"
exec "\$here/libexec/$tool" "\$@"
EOF
  chmod +x "$tmp/$tool"
done
cp scripts/gpu-bench.sh "$tmp/gpu-bench.sh"
cp scripts/gpu-bench-8k.sh scripts/gpu_bench_8k_tables.py "$tmp/"
mkdir -p "$tmp/profiles"
cp samples/profiles/looking_glass_32_8k.json samples/profiles/looking_glass_65_8k.json "$tmp/profiles/"
cp player/bench/bench_chart.py "$tmp/bench_chart.py"
for pack in "$@"; do
  cp "$pack" "$tmp/packs/"
done

# Step 5: a manifest, a check that the tools start, then the folder and the archive.
{
  echo "LFDPR player bundle"
  echo "commit: $(git rev-parse --short HEAD 2>/dev/null || echo unknown)$(git diff --quiet 2>/dev/null || echo ' (with uncommitted changes)')"
  echo "made: $(date -u +%Y-%m-%dT%H:%M:%SZ) on $(uname -m)"
  echo "needs: glibc $(objdump -T "$tmp/libexec/lfd-play" "$tmp/libexec/lfd-bench" | grep -o 'GLIBC_[0-9.]*' | sort -uV | tail -n 1 | cut -d_ -f2) or later, an OpenGL 4.5 driver with EGL"
  echo "files:"
  (cd "$tmp" && find . -type f | sort | while read -r f; do echo "  $f $(stat -c %s "$f")"; done)
} > "$tmp/MANIFEST.txt"
"$tmp/lfd-play" --help > /dev/null
"$tmp/lfd-bench" --help > /dev/null
rm -rf "$out"
mv "$tmp" "$out"
trap - EXIT
tar -czf "${out%/}.tar.gz.tmp-$$" -C "$(dirname "$out")" "$(basename "$out")"
mv "${out%/}.tar.gz.tmp-$$" "${out%/}.tar.gz"
tools=$(du -cb "$out/libexec" "$out/lib" | tail -n 1 | cut -f1)
echo "bundle-player: $out ($(du -sh "$out" | cut -f1); tools and libraries $((tools / 1024 / 1024)) MiB) and ${out%/}.tar.gz ($(du -h "${out%/}.tar.gz" | cut -f1))"
