# run2 (experiment binary, not landed as such): the compute pipelines' driver statistics
# (LLL_SHADER_STATS), the bitonic sort's block, group size and steps fused a dispatch
# (LLL_SORT_BLOCK/THREADS/FUSE, env overrides of that binary only), composite probes (LLL_EXP: 1 every
# covered pixel only dims, no puff; 2 the puff without its noise), and tile groups for sparks at full
# resolution
set -u
source .gpu/setup.sh
N=.gpu/bin/lll
mkdir -p $OUT/r
r() { local n=$1; shift 1
  timeout 90 $N render atrium --lights 256 --particle-render compute --technique lll --width 1920 --height 1080 --frames 361 --particle-lighting vertex "$@" --stats $OUT/r/$n.json -o /tmp/a.png >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
LLL_SHADER_STATS=1 timeout 60 $N render atrium --lights 256 --particle-render compute --technique lll --width 1920 --height 1080 --frames 2 --particles smoke --particle-count 65536 -o /tmp/a.png 2>&1 | grep "shader stats" > $OUT/shader-stats.txt
LLL_SHADER_STATS=1 timeout 60 $N render atrium --lights 16 --technique lll --width 1920 --height 1080 --frames 2 -o /tmp/a.png 2>&1 | grep "shader stats" >> $OUT/shader-stats.txt
wc -l $OUT/shader-stats.txt
for cfg in "4096 512 4" "4096 1024 4" "2048 1024 4" "2048 512 4" "1024 512 4" "1024 512 1" "2048 1024 2" "1024 256 4"; do
  set -- $cfg
  export LLL_SORT_BLOCK=$1 LLL_SORT_THREADS=$2 LLL_SORT_FUSE=$3
  r sort-$1-$2-$3-kf --particles smoke --particle-count 65536
  r sort-$1-$2-$3-mh --particles smoke --particle-count 1000000 --particle-resolution half
done
unset LLL_SORT_BLOCK LLL_SORT_THREADS LLL_SORT_FUSE
echo sorts $SECONDS
for e in 0 1 2; do
  export LLL_EXP=$e
  r exp$e-smoke-kf --particles smoke --particle-count 65536
  r exp$e-smoke-mh --particles smoke --particle-count 1000000 --particle-resolution half
  r exp$e-sparks-kf --particles sparks --particle-count 65536
done
unset LLL_EXP
echo exps $SECONDS
for g in 1 2 4 16; do
  r groups$g-sparks-kf --particles sparks --particle-count 65536 --particle-tile-groups $g
  r groups$g-smoke-kf --particles smoke --particle-count 65536 --particle-tile-groups $g
done
echo groups $SECONDS
cd $OUT && tar cJf r.tar.xz r && rm -rf r; ls -la; true
