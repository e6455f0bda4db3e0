R="bash .gpu/remote.sh .gpu/bin/lll"
mkdir -p $OUT/cut
run() {  # name, args...
  name=$1; shift
  $R render atrium --device gpu --width 1920 --height 1080 --frames 40 "$@" --stats $OUT/cut/$name.json --out $OUT/cut/$name.png > $OUT/cut/$name.log 2>&1
  echo "== $name: $(grep -E 'error|lll-fill-compute|shade-opaque|vpl-filter|glass |frame' $OUT/cut/$name.log | awk '{printf "%s %s  ", $2, $3}')"
}
for c in 0.02 0.01; do for k in 1 2 3 4; do run lll-c$c-t16-k$k --technique lll --tile 16 --gi vpl-only --vpl-cutoff $c --vpl-interleave $k; done; done
rm $OUT/cut/*.png
tar czf $OUT/cut.tgz -C $OUT cut && rm -rf $OUT/cut
