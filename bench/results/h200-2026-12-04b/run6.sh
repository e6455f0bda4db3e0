# run6: `lll bench --suite gi-hierarchy --technique lll --technique forward` on the landed tree:
# issue 15's rows (lll at tile 16, K = 3 and 4, beside forward at K = 1) through the bench tool.
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
timeout 540 .gpu/bin/lll bench --suite gi-hierarchy --technique lll --technique forward --out $OUT/gh > $OUT/gh.log 2>&1; echo bench rc=$? $SECONDS
tail -3 $OUT/gh.log
cd $OUT && tar cJf gh.tar.xz gh gh.log && rm -rf gh gh.log; ls -la; true
