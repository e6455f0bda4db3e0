#!/usr/bin/env bash
# The atrium's VPLs (100,000 photons; --vpl-count 512 and 5144): the hierarchy and one grid's
# cutoffs against the same VPLs summed with no cutoff (forward, 480x270, the VPLs alone, no
# ambient), and at 5,144 lll's links at 960x540, tile 16 (4,080 lists: a 1080p frame's lists at tile
# 8 do not fit lavapipe's 128 MiB storage buffers; a count past the pool is read from lll's error
# message). Not at 65,536: lavapipe ends a shader's loops after 65,535 iterations, which forward's
# loop over 64,816 lights reaches (README, known limits), so the exact sum cannot be drawn here.
set -u
LLL=${LLL:-build/lll}
here=$(cd "$(dirname "$0")" && pwd)
for n in 512 5144; do
W="--width 480 --height 270 --technique forward --ambient 0 --gi vpl-only --vpl-count $n"
$LLL render atrium $W --vpl-cutoff 1e-9 --hdr exact.pfm --out exact.png > /dev/null 2>&1
links() {
  if $LLL render atrium --technique lll --width 960 --height 540 --tile 16 --gi vpl-only "$@" --out l.png \
        --vpl-count $n --stats l.json > l.log 2>&1; then
    python3 -c "import json; t=json.load(open('l.json'))['technique_stats']; print(int(t['links_used']), 'links, mean list', round(t['mean_list'],1))"
  else
    grep -o '[0-9]* links: the' l.log | head -1
  fi
}
for a in 1 1.5 2 3 4 8; do
  $LLL render atrium $W --vpl-alpha $a --hdr h.pfm --out h_$a.png > /dev/null 2>&1
  echo "$n VPLs, alpha $a: $(python3 "$here/block_error.py" h.pfm exact.pfm)$([ $n = 5144 ] && echo "; $(links --vpl-alpha $a)")"
done
for c in 1e-3 1e-2 0.05; do
  $LLL render atrium $W --vpl-cutoff $c --hdr c.pfm --out c.png > /dev/null 2>&1
  echo "$n VPLs, one grid, cutoff $c: $(python3 "$here/block_error.py" c.pfm exact.pfm)$([ $n = 5144 ] && echo "; $(links --vpl-cutoff $c)")"
done
done
