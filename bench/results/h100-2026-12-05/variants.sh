#!/usr/bin/env bash
# Builds, from the repository root on branch wip/issue11-rebuild-probes, the binaries run.sh
# compares: /tmp/lll_base (main's tip) and probes of this branch's tree that split ThreeL's opaque
# shading (0.209 ms at 16 lights on the H200, 2.15x the ALU probe; bench/README.md, 2026-12-05
# second): r1 evaluates no light (the surface rebuild and the stores), r2 samples no texture, r3
# does not write the display image (the fused tonemap), r13 neither lights nor display.
set -euo pipefail
branch=$(git rev-parse --abbrev-ref HEAD)
git checkout -q main && ninja -C build lll >/dev/null && cp build/lll /tmp/lll_base && git checkout -q "$branch"
s=shaders/lit/shade_visibility.comp.glsl v=shaders/common/visibility_surface.glsl
cp "$s" /tmp/shade.orig && cp "$v" /tmp/vis.orig
build() {  # name no-lights no-textures no-display
  cp /tmp/shade.orig "$s" && cp /tmp/vis.orig "$v"
  sed -i "s/^#define LLL_PROBE_NO_LIGHTS 0/#define LLL_PROBE_NO_LIGHTS $2/; s/^#define LLL_PROBE_NO_DISPLAY 0/#define LLL_PROBE_NO_DISPLAY $4/" "$s"
  sed -i "s/^#define LLL_PROBE_NO_TEXTURES 0/#define LLL_PROBE_NO_TEXTURES $3/" "$v"
  ninja -C build lll >/dev/null && cp build/lll "/tmp/lll_$1"
}
build r1 1 0 0; build r2 0 1 0; build r3 0 0 1; build r13 1 0 1
cp /tmp/shade.orig "$s" && cp /tmp/vis.orig "$v" && ninja -C build lll >/dev/null
ls -la /tmp/lll_base /tmp/lll_r1 /tmp/lll_r2 /tmp/lll_r3 /tmp/lll_r13
