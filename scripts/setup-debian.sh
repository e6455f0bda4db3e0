#!/usr/bin/env bash
# Installs the Debian 12 packages lll needs to build, render and test. Idempotent: installs only
# what is missing, so .ci/run and the README commands can call it every time.
set -euo pipefail
packages=(
  build-essential cmake ninja-build ccache pkg-config
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslc spirv-tools
  libglm-dev libstb-dev libtinygltf-dev nlohmann-json3-dev libcli11-dev libfmt-dev
  libgtest-dev libtinyexr-dev gnuplot-nox libspirv-cross-c-shared-dev libembree-dev libtbb-dev
  libmeshoptimizer-dev libdraco-dev libwebp-dev
  clang-14 libclang-rt-14-dev
  libglfw3-dev libimgui-dev xvfb xauth
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then exit 0; fi
if [ "$(id -u)" -ne 0 ]; then
  echo "setup: missing Debian packages: ${missing[*]}; run this script as root (or apt-get install them)" >&2
  exit 2
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
