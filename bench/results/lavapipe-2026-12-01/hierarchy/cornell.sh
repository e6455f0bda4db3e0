#!/usr/bin/env bash
# The Cornell room's indirect light under the lighting grid hierarchy against the path-traced
# reference, lavapipe, 480x360 (as the gi-error suite), lll at tile 8 with 2 slices (the defaults).
# Run from a scratch folder; LLL is the binary; python3 block_error.py prints the 8x8-block error.
set -eu
LLL=${LLL:-build/lll}
here=$(cd "$(dirname "$0")" && pwd)
[ -f ref.pfm ] || $LLL reference cornell --indirect --spp 2048 --width 480 --height 360 --out ref.pfm
for n in 512 5144 65536; do
  p=$(( 3*n > 100000 ? 3*n : 100000 ))
  for a in 1 1.5 2 3; do
    $LLL render cornell --technique lll --gi vpl-only --ambient 0 --vpl-count $n --photons $p --vpl-alpha $a \
      --width 480 --height 360 --hdr s.pfm --out s.png --stats s_${n}_$a.json > /dev/null 2>&1
    m=$(python3 -c "import json; d=json.load(open('s_${n}_$a.json')); t=d['technique_stats']; print(d['lights'], round(t['mean_list'],1), t['longest_list'])")
    echo "$n VPLs, alpha $a: $(python3 "$here/block_error.py" s.pfm ref.pfm); lights / mean list / longest: $m"
  done
done
# One grid at 5,144 VPLs, the short cutoff (the default one's pool does not fit lavapipe's 128 MiB).
$LLL render cornell --technique lll --gi vpl-only --ambient 0 --vpl-count 5144 --vpl-cutoff 0.05 \
  --width 480 --height 360 --hdr s.pfm --out s.png --stats short.json > /dev/null 2>&1
echo "5144 VPLs, one grid, cutoff 0.05: $(python3 "$here/block_error.py" s.pfm ref.pfm); mean list $(python3 -c "import json; print(round(json.load(open('short.json'))['technique_stats']['mean_list'],1))")"
