reset
set terminal pngcairo noenhanced size 1280,800 font 'sans,11'
set output 'gi-hierarchy.png'
set title "Frame time against VPL count (every level's), the lighting grid hierarchy: atrium, 1920x1080\nNVIDIA H200, NVIDIA 580.159.04, commit f7d6f179245e-dirty"
set xlabel "virtual point lights (the scene's own lights left out: --gi vpl-only)"
set ylabel "GPU frame time, ms (median; bars: min to max)"
set logscale xy
set format x '%.0f'
set xrange [408:2027970]
set xtics (510, 662, 5099, 7483, 7489, 64816, 105214, 1045625, 1622376)
set grid xtics ytics mytics
set key top left box opaque
plot 'gi-hierarchy.dat' index 0 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 1 title "forward, hierarchy 1.5", 'gi-hierarchy.dat' index 1 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 2 title "lll/compute, hierarchy 1.5", 'gi-hierarchy.dat' index 2 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 3 title "lll/compute, cutoff 0.05", 'gi-hierarchy.dat' index 3 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 4 title "lll/compute/interleave2, hierarchy 1.5", 'gi-hierarchy.dat' index 4 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 5 title "lll/compute/interleave3 tile 16, hierarchy 1.5", 'gi-hierarchy.dat' index 5 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 6 title "lll/compute/interleave4 tile 16, hierarchy 1.5", 'gi-hierarchy.dat' index 6 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 7 title "lll/compute, hierarchy 1", 'gi-hierarchy.dat' index 7 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 8 title "lll/compute, hierarchy 3"
