#!/usr/bin/env bash
# Builds lll and renders the default scene (the atrium, 110 lights) to a PNG.
# Usage: scripts/render-default.sh [OUT.png] [extra `lll render` options...]
# It renders with the light linked list on whatever device `lll devices` ranks first: a GPU, or
# lavapipe on a machine without one (about a second at this size).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-atrium.png}
shift || true
bash "$root/scripts/build.sh" "$root/build"
"$root/build/lll" render --technique lll --width 1280 --height 720 --out "$out" "$@"
echo "wrote $out"
