reset
set terminal pngcairo noenhanced size 1280,800 font 'sans,11'
set output 'scaling.png'
set title "Frame time against light count: atrium, 1920x1080\nNVIDIA H200, NVIDIA 580.159.04, commit 51c672b8d00f-dirty"
set xlabel "lights in the scene (its own plus the random ones added)"
set ylabel "GPU frame time, ms (median; bars: min to max)"
set logscale xy
set format x '%.0f'
set xrange [100.8:82057.5]
set xtics (126, 174, 366, 1134, 4206, 16494, 65646)
set grid xtics ytics mytics
set key top left box opaque
plot 'scaling.dat' index 0 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 1 title "lll/shells", 'scaling.dat' index 1 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 2 title "lll/ray", 'scaling.dat' index 2 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 3 title "lll/compute", 'scaling.dat' index 3 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 4 title "lll/compute/hardware-raster", 'scaling.dat' index 4 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 5 title "lll/compute/gbuffer", 'scaling.dat' index 5 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 6 title "lll/compute/fragment-shade", 'scaling.dat' index 6 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 7 title "tiled", 'scaling.dat' index 7 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 8 title "clustered"
