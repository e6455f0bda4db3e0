# run5.sh (lll = b35a0c7's tree; --lll-fill-splits swept)
set -u
source .gpu/setup.sh
N=.gpu/bin/lll
mkdir -p $OUT/r
r() { local n=$1; shift
  timeout 90 $N render "$@" --stats $OUT/r/$n.json --out /tmp/a.png >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
W="--width 1920 --height 1080"
for rep in 1 2; do
for s in 1 2 4 16 64; do
  r t16-s$s-$rep threel16 --technique lll $W --frames 150 --lll-fill-splits $s
  r t256-s$s-$rep threel256 --technique lll $W --frames 40 --lll-fill-splits $s
  r a1024-s$s-$rep atrium --lights 1024 --technique lll $W --frames 100 --lll-fill-splits $s
  [ $rep = 1 ] || continue
  r t16k-s$s-$rep threel16 --technique lll --width 3840 --height 2160 --frames 60 --lll-fill-splits $s
  r atrium-s$s-$rep atrium --technique lll $W --frames 100 --lll-fill-splits $s
  r vpl4-s$s-$rep atrium --gi vpl-only --vpl-interleave 4 --technique lll $W --frames 15 --lll-fill-splits $s
done; done
echo done $SECONDS
cd $OUT && tar cJf r.tar.xz r && rm -rf r; ls -la
