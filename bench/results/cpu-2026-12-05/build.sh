#!/usr/bin/env bash
# Builds mesh_order.cpp against the repository's build (run from the repository root after
# `ninja -C build lll`), links it as the lll executable is linked, and runs it on the default
# scene and the glTF assets: bench/README.md, "CPU only, 2026-12-05 (third)".
set -euo pipefail
libs=$(grep -A2 '^build lll:' build/build.ninja | sed -n 's/.*LINK_LIBRARIES = //p')
(cd build && g++ -std=c++20 -O2 -I../src -I../shaders -Igenerated \
  ../bench/results/cpu-2026-12-05/mesh_order.cpp -o /tmp/mesh_order $libs)
/tmp/mesh_order threel16 assets/cave/cave.gltf assets/garage/garage.gltf assets/camp/camp.gltf \
  assets/space/space.gltf
