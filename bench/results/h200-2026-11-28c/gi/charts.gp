reset
set terminal pngcairo noenhanced size 1280,800 font 'sans,11'
set output 'gi.png'
set title "Frame time against VPL count (the VPLs alone), two VPL cutoffs: atrium, 1920x1080\nNVIDIA H200, NVIDIA 580.159.04, commit 3fe664b82d75-dirty"
set xlabel "virtual point lights (the scene's own lights left out: --gi vpl-only)"
set ylabel "GPU frame time, ms (median; bars: min to max)"
set logscale xy
set format x '%.0f'
set xrange [408:1307032.5]
set xtics (510, 5099, 64816, 1045626)
set grid xtics ytics mytics
set key top left box opaque
plot 'gi.dat' index 0 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 1 title "forward, cutoff 0.001", 'gi.dat' index 1 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 2 title "deferred, cutoff 0.001", 'gi.dat' index 2 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 3 title "prepass, cutoff 0.001", 'gi.dat' index 3 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 4 title "lll/compute, cutoff 0.001", 'gi.dat' index 4 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 5 title "tiled, cutoff 0.001", 'gi.dat' index 5 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 6 title "clustered, cutoff 0.001", 'gi.dat' index 6 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 7 title "forward, cutoff 0.05", 'gi.dat' index 7 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 8 title "deferred, cutoff 0.05", 'gi.dat' index 8 using 1:2:3:4 with yerrorlines lw 2 dt 2 pt 4 lc 9 title "prepass, cutoff 0.05", 'gi.dat' index 9 using 1:2:3:4 with yerrorlines lw 2 dt 2 pt 5 lc 10 title "lll/compute, cutoff 0.05", 'gi.dat' index 10 using 1:2:3:4 with yerrorlines lw 2 dt 2 pt 6 lc 11 title "tiled, cutoff 0.05", 'gi.dat' index 11 using 1:2:3:4 with yerrorlines lw 2 dt 2 pt 7 lc 12 title "clustered, cutoff 0.05"
reset
set terminal pngcairo noenhanced size 1280,800 font 'sans,11'
set output 'gi-error.png'
set title "Instant radiosity against the path-traced indirect light, per VPL cutoff: cornell, 480x360\nNVIDIA H200, NVIDIA 580.159.04, commit 3fe664b82d75-dirty"
set xlabel "virtual point lights (the scene's own lights left out: --gi vpl-only)"
set ylabel "relative RMS error against the path-traced reference (8x8-pixel block means)"
set logscale xy
set format x '%.0f'
set xrange [43.2:81303.75]
set xtics (54, 452, 5024, 65043)
set grid xtics ytics mytics
set key top left box opaque
plot 'gi-error.dat' index 0 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 1 title "cutoff 1e-06", 'gi-error.dat' index 1 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 2 title "cutoff 0.001", 'gi-error.dat' index 2 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 3 title "cutoff 0.05"
