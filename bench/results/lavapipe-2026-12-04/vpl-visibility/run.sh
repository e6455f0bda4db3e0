# The atrium's VPL light against the path-traced indirect light, with and without the VPLs'
# visibility (`lll reference --vpls`), on lavapipe's host (2 cores), commit of this folder's run.
# Usage from the repository root: bash bench/results/lavapipe-2026-12-04/vpl-visibility/run.sh OUTDIR
set -eu
o=$1; mkdir -p "$o"; d=$(dirname "$0")
R="--width 240 --height 135"
build/lll render atrium --gi vpl-only --ambient 0 $R --technique forward --out "$o/gpu.png" --hdr "$o/gpu.pfm"
build/lll reference atrium --indirect --spp 256 $R --out "$o/ref.pfm"
for m in unshadowed shadowed; do
  build/lll reference atrium --vpls $m --spp 4 $R --out "$o/grid-$m.pfm"
  build/lll reference atrium --vpls $m --vpl-hierarchy none --spp 2 $R --out "$o/one-$m.pfm"
done
# Every deposit its own VPL (20,000 photons), at a quarter of the pixels.
R4="--width 120 --height 68"
build/lll reference atrium --indirect --spp 512 $R4 --out "$o/ref4.pfm"
for m in unshadowed shadowed; do
  build/lll reference atrium --vpls $m --vpl-count 0 --vpl-hierarchy none --photons 20000 --spp 1 $R4 \
    --out "$o/deposits-$m.pfm"
done
p() { "${PYTHON:-/usr/bin/python3}" "$d/compare.py" "$o/$1.pfm" "$o/$2.pfm"; }
p gpu grid-unshadowed
for f in gpu grid-unshadowed grid-shadowed one-unshadowed one-shadowed; do p $f ref; done
for f in deposits-unshadowed deposits-shadowed; do p $f ref4; done
