# run2: --particle-tile-groups sweep with the bitmap + opaque-group stop build (render --stats, one settled frame each)
set -u
source .gpu/setup.sh
N=.gpu/bin/lll
mkdir -p $OUT/r
r() { local n=$1; shift
  timeout 60 $N render atrium --lights 256 --particles smoke --particle-render compute --technique lll --width 1920 --height 1080 --frames 361 "$@" --stats $OUT/r/$n.json -o /tmp/a.png >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
for rep in 1 2 3; do
  for g in 4 8 16 32; do r m-q-$g-$rep --particle-count 1000000 --particle-lighting vertex --particle-resolution quarter --particle-tile-groups $g; done
  for g in 8 16 32; do r m-h-$g-$rep --particle-count 1000000 --particle-lighting vertex --particle-resolution half --particle-tile-groups $g; done
  for g in 1 2 4 8; do r k-f-$g-$rep --particle-count 65536 --particle-lighting vertex --particle-tile-groups $g; done
  for g in 4 8 16; do r k-h-$g-$rep --particle-count 65536 --particle-lighting vertex --particle-resolution half --particle-tile-groups $g; done
  for g in 4 8 16; do r k-q-$g-$rep --particle-count 65536 --particle-lighting vertex --particle-resolution quarter --particle-tile-groups $g; done
  echo rep $rep $SECONDS
done
cd $OUT && tar cJf r.tar.xz r && rm -rf r; ls -la; true
