#!/usr/bin/env bash
# Builds lll and renders the default scene (the atrium, 110 lights) to a PNG.
# Usage: scripts/render-default.sh [OUT.png] [extra `lll render` options...]
# On a GPU it renders with the light linked list. On a CPU device (lavapipe) it renders with the
# forward reference instead: lavapipe runs the list walk's fragment shader ~70x slower than the
# same walk in compute (bench/README.md), which would take many minutes at this size.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-atrium.png}
shift || true
bash "$root/scripts/build.sh" "$root/build"
technique=lll
if ! "$root/build/lll" devices | grep -v 'unusable' | grep -Eq '\((discrete|integrated|virtual)'; then
  technique=forward
  echo "no GPU found: rendering with the forward reference on the CPU device"
fi
"$root/build/lll" render --technique "$technique" --width 1280 --height 720 --out "$out" "$@"
echo "wrote $out"
