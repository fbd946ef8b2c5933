#!/usr/bin/env bash
# Installs every build, test and run-time dependency from Debian packages.
# Idempotent and non-interactive; run as root (or with sudo) on Debian 12.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git ninja-build
  libglm-dev nlohmann-json3-dev libtinygltf-dev libstb-dev libopenmesh-dev
  libopenimageio-dev openimageio-tools libxxhash-dev zlib1g-dev libcli11-dev libosd-dev libzstd-dev libsquish-dev
  libdraco-dev libmeshoptimizer-dev libwebp-dev
  libavformat-dev libavcodec-dev libswscale-dev libavutil-dev
  libegl-dev libepoxy-dev libglfw3-dev libegl-mesa0 libgl1-mesa-dri mesa-utils
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth xdotool assimp-testmodels glslang-tools ffmpeg
  clang libclang-rt-14-dev lld python3 python3-matplotlib
  blender
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]})); then
  echo "setup: installing ${#missing[@]} package(s): ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "setup: all packages present"
fi
