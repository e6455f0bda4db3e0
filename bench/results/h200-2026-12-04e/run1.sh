# run1: the list walked one link at a time (v1: nextLink, the light evaluated where the link's
# bounds hold the point) and with the head read from the workgroup's first pixel (v2: the working
# tree), against 1f6bf75 (v0). lll at tile 16 (and 8) on ThreeL's 16 and 256 lights and the atrium
# with 1,024 and 65,536 random lights, 1080p, `lll render --frames 200 --stats`, three runs in
# rotating order; images kept of the first run.
set -u
source .gpu/setup.sh
E=.gpu/extra
mkdir -p $OUT/r $OUT/img
bin() { case $1 in v2) echo .gpu/bin/lll;; *) echo $E/lll_$1;; esac; }
W="--width 1920 --height 1080"
one() {  # variant rep name args...
  local v=$1 rep=$2 name=$3; shift 3
  local I=/tmp/a.png; [ $rep = 1 ] && I=$OUT/img/$v-$name.png
  timeout 60 $(bin $v) render "$@" --technique lll $W --frames 200 --stats $OUT/r/$v-$name-$rep.json --out $I >/dev/null 2>&1 || echo fail $v $name
}
for rep in 1 2 3; do
  case $rep in 1) order="v0 v1 v2";; 2) order="v2 v0 v1";; 3) order="v1 v2 v0";; esac
  for v in $order; do
    one $v $rep threel16 threel16
    one $v $rep threel256 threel256
    one $v $rep threel16-t8 threel16 --tile 8
    one $v $rep atrium1024 atrium --lights 1024
    one $v $rep atrium65536 atrium --lights 65536
  done
done
echo renders $SECONDS
cd $OUT && tar cJf r.tar.xz r && tar cf img.tar img && rm -rf r img; ls -la; true
