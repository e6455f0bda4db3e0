reset
set terminal pngcairo noenhanced size 1280,800 font 'sans,11'
set output 'gi-error.png'
set title "Instant radiosity against the path-traced indirect light, per VPL cutoff: cornell, 480x360\nNVIDIA H200, NVIDIA 580.159.04, commit 04f31712f566-dirty"
set xlabel "virtual point lights (the scene's own lights left out: --gi vpl-only)"
set ylabel "relative RMS error against the path-traced reference (8x8-pixel block means)"
set logscale xy
set format x '%.0f'
set xrange [43.2:81303.75]
set xtics (54, 452, 5024, 65043)
set grid xtics ytics mytics
set key top left box opaque
plot 'gi-error.dat' index 0 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 1 title "cutoff 1e-06", 'gi-error.dat' index 1 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 2 title "cutoff 1e-06, interleave 2", 'gi-error.dat' index 2 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 3 title "cutoff 0.001", 'gi-error.dat' index 3 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 4 title "cutoff 0.001, interleave 2", 'gi-error.dat' index 4 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 5 title "cutoff 0.05", 'gi-error.dat' index 5 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 6 title "cutoff 0.05, interleave 2", 'gi-error.dat' index 6 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 7 title "range 8 m"
