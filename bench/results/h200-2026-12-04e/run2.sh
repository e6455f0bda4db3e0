# run2: the link-at-a-time walk also for glass and particles (v3: the working tree) against
# 1f6bf75 (v0), and three probe builds of v3 that locate threel16's opaque shading beyond the ALU
# probe (not kept): p1 rebuilds the surface and evaluates no light, p2 evaluates every light by
# index with no list (as forward, without its shared memory), p3 reads the list head before the
# surface rebuild. `lll render --frames 200 --stats`, 1080p, three runs in rotating order.
set -u
source .gpu/setup.sh
E=.gpu/extra
mkdir -p $OUT/r $OUT/img
bin() { case $1 in v3) echo .gpu/bin/lll;; *) echo $E/lll_$1;; esac; }
W="--width 1920 --height 1080"
one() {  # variant rep name args...
  local v=$1 rep=$2 name=$3; shift 3
  local I=/tmp/a.png; [ $rep = 1 ] && case $v-$name in v0-threel16|v3-threel16|v0-atrium65536|v3-atrium65536|v0-smoke|v3-smoke) I=$OUT/img/$v-$name.png;; esac
  timeout 60 $(bin $v) render "$@" $W --frames 200 --stats $OUT/r/$v-$name-$rep.json --out $I >/dev/null 2>&1 || echo fail $v $name
}
for rep in 1 2 3; do
  case $rep in 1) order="v0 v3 p1 p2 p3";; 2) order="p3 p2 p1 v3 v0";; 3) order="v3 p1 v0 p3 p2";; esac
  for v in $order; do
    one $v $rep threel16 threel16 --technique lll
    one $v $rep threel256 threel256 --technique lll
    one $v $rep atrium1024 atrium --lights 1024 --technique lll
    case $v in v0|v3)
      one $v $rep atrium65536 atrium --lights 65536 --technique lll
      one $v $rep smoke atrium --lights 1024 --technique lll --particles smoke --particle-count 65536;;
    esac
  done
done
echo renders $SECONDS
cd $OUT && tar cJf r.tar.xz r && tar cf img.tar img && rm -rf r img; ls -la; true
