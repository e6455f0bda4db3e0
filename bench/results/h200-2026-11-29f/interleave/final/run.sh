R="bash .gpu/remote.sh .gpu/bin/lll"
mkdir -p $OUT/j
run() {  # name, args...
  name=$1; shift
  $R render atrium --device gpu --width 1920 --height 1080 --frames 40 "$@" --stats $OUT/j/$name.json --out $OUT/j/$name.png > $OUT/j/$name.log 2>&1
  echo "== $name: $(grep -E 'error|lll-fill-compute|shade-opaque|vpl-filter|glass |frame' $OUT/j/$name.log | awk '{printf "%s %s  ", $2, $3}')"
}
GI="--gi vpl-only --vpl-cutoff 0.05"
for k in 1 2 3 4; do run lll-t8-k$k --technique lll $GI --vpl-interleave $k; done
for k in 1 2 3 4; do run lll-t16-k$k --technique lll --tile 16 $GI --vpl-interleave $k; done
for k in 1 2 3; do run tiled-k$k --technique tiled $GI --vpl-interleave $k; done
for k in 1 2 3; do run lll-gi-k$k --technique lll --gi vpl --vpl-cutoff 0.05 --lights 256 --vpl-interleave $k; done
GI="--gi vpl-only --vpl-cutoff 0.05 --vpl-count 65536 --photons 196608"
for k in 1 2 3; do run lll65-t16-k$k --technique lll --tile 16 $GI --vpl-interleave $k; done
cp $OUT/j/lll-t8-k1.png $OUT/j/lll-t8-k2.png $OUT/j/lll-t8-k3.png $OUT/j/lll-gi-k2.png $OUT/
rm $OUT/j/*.png
tar czf $OUT/il3.tgz -C $OUT j && rm -rf $OUT/j
