# run2: particles-bin in three timed passes (count, scan, scatter; the tree of this run, with
# run1's batch): the smoke bench; settled smoke at full resolution (vertex-lit, `lll render --stats`,
# two runs) with tile groups 1 to 32 at 65,536, 131,072, 262,144 and a million particles; a million
# atlas-lit with 1 and 16.
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
mkdir -p $OUT/r
r() { local n=$1; shift
  timeout 90 .gpu/bin/lll render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
W="--width 1920 --height 1080"
S="atrium --lights 256 --particle-render compute --technique lll $W --frames 361 --particles smoke"
timeout 150 .gpu/bin/lll bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --frames 15 --warmup 5 --out $OUT/bench-split > $OUT/bench-split.log 2>&1; echo bench rc=$? $SECONDS
for rep in 1 2; do
  for g in 1 2 4; do r k65-g$g-$rep $S --particle-lighting vertex --particle-count 65536 --particle-tile-groups $g --out /tmp/a.png; done
  for g in 1 2 4 8; do r k131-g$g-$rep $S --particle-lighting vertex --particle-count 131072 --particle-tile-groups $g --out /tmp/a.png; done
  for g in 1 4 8 16; do r k262-g$g-$rep $S --particle-lighting vertex --particle-count 262144 --particle-tile-groups $g --out /tmp/a.png; done
  for g in 8 16 32; do r m1-g$g-$rep $S --particle-lighting vertex --particle-count 1000000 --particle-tile-groups $g --out /tmp/a.png; done
done
for g in 1 16; do r m1atlas-g$g-1 $S --particle-lighting atlas --particle-count 1000000 --particle-tile-groups $g --out /tmp/a.png; done
echo renders $SECONDS
cd $OUT && tar cJf r.tar.xz r bench-* *.log && rm -rf r bench-* *.log; ls -la; true
