R="bash .gpu/remote.sh .gpu/bin/lll"
for spec in "threel16|lll|" "atrium|lll|" "atrium|lll|--gi vpl-only --vpl-cutoff 0.05" "atrium|tiled|--gi vpl-only --vpl-cutoff 0.05" "atrium|forward|" "assets/camp/camp.gltf|lll|--lights 1024"; do
  IFS='|' read scene tech extra <<< "$spec"
  for g in raster compute; do
    echo "== $scene $tech $extra glass=$g"
    $R render $scene --device gpu --technique $tech $extra --glass $g --width 1920 --height 1080 --frames 40 --out $OUT/$(basename $scene .gltf)-$tech-$g${extra:+-gi}.png --stats $OUT/s.json 2>&1 | grep -E "glass|shade-opaque|frame|error"
    grep -o '"glass-[a-z-]*": *[0-9.e+-]*' $OUT/s.json | tr '\n' ' '; echo
  done
done
