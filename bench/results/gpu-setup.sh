# Sourced on the GPU machine from the repository root (copied to .gpu/setup.sh) by every H200 run
# from h200-2026-12-02b on: unpacks .gpu/pack.tar.xz, installs the loaders, points Vulkan at
# NVIDIA's driver and the packed validation layer.
g=$(pwd)/.gpu
(cd "$g" && xz -dc pack.tar.xz | tar xf -)
for f in "$g"/debs/*.deb; do dpkg -x "$f" /; done
ldconfig
export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
export LD_LIBRARY_PATH="$g/lib"
export VK_LAYER_PATH="$g/extra/layers"
mkdir -p /work && ln -sfn "$(pwd)" /work/main
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv,noheader || true
