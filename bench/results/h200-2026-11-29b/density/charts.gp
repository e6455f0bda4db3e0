reset
set terminal pngcairo noenhanced size 1280,800 font 'sans,11'
set output 'density.png'
set title "Frame time against light count at constant light density: atrium, 1920x1080\nNVIDIA H200, NVIDIA 580.159.04, commit a12a2f06c503-dirty"
set xlabel "lights in the scene (its own plus the random ones added)"
set ylabel "GPU frame time, ms (median; bars: min to max)"
set logscale xy
set format x '%.0f'
set xrange [907.2:5243017.5]
set xtics (1134, 4206, 16494, 65646, 262254, 1048686, 4194414)
set grid xtics ytics mytics
set key top left box opaque
plot 'density.dat' index 0 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 1 title "forward", 'density.dat' index 1 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 2 title "deferred", 'density.dat' index 2 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 3 title "prepass", 'density.dat' index 3 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 4 title "lll/compute/slices2", 'density.dat' index 4 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 5 title "tiled", 'density.dat' index 5 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 6 title "clustered"
reset
set terminal pngcairo noenhanced size 1280,800 font 'sans,11'
set output 'density-passes.png'
set title "Light data and shading against light count at constant light density: atrium, 1920x1080\nNVIDIA H200, NVIDIA 580.159.04, commit a12a2f06c503-dirty"
set xlabel "lights in the scene (its own plus the random ones added)"
set ylabel "GPU ms (median): the technique's own passes dashed, shade-opaque + glass solid"
set logscale xy
set format x '%.0f'
set xrange [907.2:5243017.5]
set xtics (1134, 4206, 16494, 65646, 262254, 1048686, 4194414)
set grid xtics ytics mytics
set key top left box opaque
plot 'density-passes.dat' index 0 using 1:2:3:4 with linespoints lw 2 pt 7 lc 1 title "forward: shade-opaque + glass", 'density-passes.dat' index 1 using 1:2:3:4 with linespoints dt 2 lw 2 pt 6 lc 2 title "deferred: own passes", 'density-passes.dat' index 2 using 1:2:3:4 with linespoints lw 2 pt 7 lc 2 title "deferred: shade-opaque + glass", 'density-passes.dat' index 3 using 1:2:3:4 with linespoints dt 2 lw 2 pt 6 lc 3 title "prepass: own passes", 'density-passes.dat' index 4 using 1:2:3:4 with linespoints lw 2 pt 7 lc 3 title "prepass: shade-opaque + glass", 'density-passes.dat' index 5 using 1:2:3:4 with linespoints dt 2 lw 2 pt 6 lc 4 title "lll/compute/slices2: own passes", 'density-passes.dat' index 6 using 1:2:3:4 with linespoints lw 2 pt 7 lc 4 title "lll/compute/slices2: shade-opaque + glass", 'density-passes.dat' index 7 using 1:2:3:4 with linespoints dt 2 lw 2 pt 6 lc 5 title "tiled: own passes", 'density-passes.dat' index 8 using 1:2:3:4 with linespoints lw 2 pt 7 lc 5 title "tiled: shade-opaque + glass", 'density-passes.dat' index 9 using 1:2:3:4 with linespoints dt 2 lw 2 pt 6 lc 6 title "clustered: own passes", 'density-passes.dat' index 10 using 1:2:3:4 with linespoints lw 2 pt 7 lc 6 title "clustered: shade-opaque + glass"
reset
set terminal pngcairo noenhanced size 1280,800 font 'sans,11'
set output 'density-memory.png'
set title "Lighting-data memory against light count at constant light density: atrium, 1920x1080\nNVIDIA H200, NVIDIA 580.159.04, commit a12a2f06c503-dirty"
set xlabel "lights in the scene (its own plus the random ones added)"
set ylabel "GPU memory of the lighting data, MiB (depth + the technique's buffers)"
set logscale xy
set format x '%.0f'
set xrange [907.2:5243017.5]
set xtics (1134, 4206, 16494, 65646, 262254, 1048686, 4194414)
set grid xtics ytics mytics
set key top left box opaque
plot 'density-memory.dat' index 0 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 1 title "forward", 'density-memory.dat' index 1 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 2 title "deferred", 'density-memory.dat' index 2 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 3 title "prepass", 'density-memory.dat' index 3 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 4 title "lll/compute/slices2", 'density-memory.dat' index 4 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 5 title "tiled", 'density-memory.dat' index 5 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 6 title "clustered"
