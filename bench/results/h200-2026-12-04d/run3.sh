# run3: issue 11's shading with every light record in shared memory where the scene has at most 256
# (shl: the working tree of this run) against ffe3237 (head): the threel bench of each, lll only,
# twice in turn; the smoke bench of ffe3237 (the particle tile groups' new default).
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
bin() { case $1 in shl) echo .gpu/bin/lll;; *) echo $E/lll_$1;; esac; }
for rep in 1 2; do for v in head shl; do
  timeout 100 $(bin $v) bench --suite threel --technique lll --out $OUT/bench-$v-$rep > $OUT/bench-$v-$rep.log 2>&1; echo bench $v rc=$? $SECONDS
done; done
timeout 150 $E/lll_head bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --frames 15 --warmup 5 --out $OUT/bench-smoke > $OUT/bench-smoke.log 2>&1; echo bench smoke rc=$? $SECONDS
cd $OUT && tar cJf r.tar.xz bench-* *.log && rm -rf bench-* *.log; ls -la; true
