R="bash .gpu/remote.sh .gpu/bin/lll"
mkdir -p $OUT/json65
run() {  # name, args...
  name=$1; shift
  $R render atrium --device gpu --width 1920 --height 1080 --frames 40 "$@" --stats $OUT/json65/$name.json --out $OUT/json65/$name.png > $OUT/json65/$name.log 2>&1
  echo "== $name: $(grep -E 'error|lll-fill-compute|shade-opaque|vpl-filter|glass |frame' $OUT/json65/$name.log | awk '{printf "%s %s  ", $2, $3}')"
}
GI="--gi vpl-only --vpl-cutoff 0.05 --vpl-count 65536 --photons 196608"
for k in 1 2 3 4; do run lll65-t8-k$k --technique lll $GI --vpl-interleave $k; done
for k in 1 2 3 4; do run lll65-t16-k$k --technique lll --tile 16 $GI --vpl-interleave $k; done
for k in 1 2 3; do run tiled65-k$k --technique tiled $GI --vpl-interleave $k; done
GI="--gi vpl-only --vpl-cutoff 0.05"
for k in 1 2 3 4; do run lll5-t16-s1-k$k --technique lll --tile 16 --lll-slices 1 $GI --vpl-interleave $k; done
rm $OUT/json65/*.png
tar czf $OUT/il65.tgz -C $OUT json65 && rm -rf $OUT/json65
