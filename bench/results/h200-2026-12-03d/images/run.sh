set -u
source .gpu/setup.sh
N=.gpu/bin/lll; O=.gpu/extra/lll_head
mkdir -p $OUT/img
W="--width 1920 --height 1080"
for v in old new; do
  B=$N; [ $v = old ] && B=$O
  for k in 3 4; do timeout 60 $B render atrium --gi vpl-only --vpl-interleave $k --technique lll $W --frames 2 --out $OUT/img/$v-vpl$k.png >/dev/null 2>&1 || echo fail $v $k; done
  timeout 60 $B render atrium --gi vpl --vpl-interleave 4 --technique lll $W --frames 2 --out $OUT/img/$v-vplg4.png >/dev/null 2>&1 || echo fail g4
done
timeout 60 $N render atrium --gi vpl-only --technique lll $W --frames 2 --out $OUT/img/new-vpl1.png >/dev/null 2>&1
cd $OUT && tar cf img1.tar img/old-* && tar cf img2.tar img/new-* && rm -rf img; ls -la
