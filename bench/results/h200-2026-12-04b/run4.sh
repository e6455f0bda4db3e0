# run4: the particle composite's early stop at a pixel's transmittance 1/256 (t256) and 1/64 (t64)
# instead of 1/1024 (base = 95f57d6): the settled plume of 65,536 smoke particles at 1080p, its
# image from the compute path of each and from the raster path (the reference), the smoke bench.
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
mkdir -p $OUT/img
S="atrium --lights 256 --technique lll --width 1920 --height 1080 --frames 361 --particles smoke --particle-count 65536"
timeout 120 $E/lll_base render $S --particle-render raster --particle-lighting vertex -o $OUT/img/raster-vertex.png > /dev/null 2>$OUT/img/raster.err || echo fail raster
for v in base t256 t64; do
  for l in vertex atlas; do
    timeout 90 $E/lll_$v render $S --particle-render compute --particle-lighting $l -o $OUT/img/$v-$l.png > /dev/null 2>$OUT/img/$v-$l.err || echo fail $v $l
  done
done
echo renders $SECONDS
for v in base t256 t64; do
  timeout 120 $E/lll_$v bench --suite smoke --technique lll --particle-count 65536 --out $OUT/$v > $OUT/$v.log 2>&1; echo $v rc=$? $SECONDS
done
cd $OUT && tar cJf r.tar.xz base t256 t64 *.log img/*.err && tar cf img1.tar img/raster-*.png img/base-*.png && tar cf img2.tar img/t256-*.png && tar cf img3.tar img/t64-*.png && rm -rf img base t256 t64 *.log; ls -la; true
