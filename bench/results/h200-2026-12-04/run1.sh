# run1: VPLs' specular lobes widened by their patch (73138b9, new) against 94d612a (old): the atrium's
# VPLs at K = 1, 3, 4 (images and times), + the atrium's lights, 65,536 VPLs; the GI, interleaving,
# glass and analytic tests on the GPU with validation.
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
N=.gpu/bin/lll; O=.gpu/extra/lll_old; E=.gpu/extra
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
W="--width 1920 --height 1080"
for rep in 1 2; do
for v in new old; do
  B=$N; [ $v = old ] && B=$O
  for k in 1 3 4; do
    img=/tmp/a.png; [ $rep = 1 ] && img=$OUT/img/$v-vpl$k.png
    f=15; [ $k = 1 ] && f=8
    r $v-vpl$k-$rep $B atrium --gi vpl-only --vpl-interleave $k --technique lll $W --frames $f --out $img
  done
  r $v-vpl65k4-$rep $B atrium --gi vpl-only --vpl-count 65536 --photons 196608 --vpl-interleave 4 --technique lll $W --frames 10 --out /tmp/a.png
  r $v-vplg4-$rep $B atrium --gi vpl --vpl-interleave 4 --technique lll $W --frames 15 --out /tmp/a.png
done; done
echo renders done $SECONDS
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 200 $E/lll_tests --gtest_filter='InterleavedVpls.*:Gi.*:ComputeGlass.*:ShadingPaths/Analytic.*:GlassAndParticles.*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED|\[ gi" $OUT/tests.log | head -12
cd $OUT && tar cJf r.tar.xz r tests.log && tar cf img-new.tar img/new-* && tar cf img-old.tar img/old-* && rm -rf r img tests.log; ls -la; true
