# run6: particles-bin with 4 or 8 invocations a particle whose disc the first computes and shares
# through shared memory (sbin4, sbin8; run5's bin4 / bin8 had every lane compute it), against one a
# particle (base, 4f2aebc): the smoke bench of each, twice, interleaved.
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
bin() { case $1 in sbin8) echo .gpu/bin/lll;; *) echo $E/lll_$1;; esac; }
for n in 1 2; do for v in base sbin4 sbin8; do
  timeout 150 $(bin $v) bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --frames 15 --warmup 5 --out $OUT/bench-$v-$n > $OUT/bench-$v-$n.log 2>&1; echo bench $v rc=$? $SECONDS
done; done
cd $OUT && tar cJf r.tar.xz bench-* && rm -rf bench-*; ls -la; true
