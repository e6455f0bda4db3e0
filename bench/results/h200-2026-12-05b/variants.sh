#!/usr/bin/env bash
# Builds the binaries run.sh compares, from the repository root on branch
# wip/issue11-walk-and-rebuild: /tmp/lll_base (main's tip: the link-at-a-time walk), /tmp/lll_t1
# (this branch: the rebuild samples only the textures a material has), and probes of t1's tree
# that set lll/lighting.glsl's LLL_LOOKAHEAD / LLL_PROBE_COMPACT_ONLY: q1, q3 (links read ahead down
# a segment), c1 (compact links only, no format test per link), q1c (both). run.sh runs t1 a
# second time as t2, with LLL_PROBE_COMPUTED_LOD=1 (src/render/visibility.cpp).
set -euo pipefail
branch=$(git rev-parse --abbrev-ref HEAD)
f=shaders/lighting/lll/lighting.glsl
git checkout -q main && ninja -C build lll >/dev/null && cp build/lll /tmp/lll_base && git checkout -q "$branch"
cp "$f" /tmp/lighting.orig
build() {
  sed -i "s/^#define LLL_LOOKAHEAD [0-9]*/#define LLL_LOOKAHEAD $2/; s/^#define LLL_PROBE_COMPACT_ONLY [0-9]*/#define LLL_PROBE_COMPACT_ONLY $3/" "$f"
  ninja -C build lll >/dev/null && cp build/lll "/tmp/lll_$1"
}
build t1 0 0; build q1 1 0; build q3 3 0; build c1 0 1; build q1c 1 1
cp /tmp/lighting.orig "$f" && ninja -C build lll >/dev/null
ls -la /tmp/lll_base /tmp/lll_t1 /tmp/lll_q1 /tmp/lll_q3 /tmp/lll_c1 /tmp/lll_q1c
