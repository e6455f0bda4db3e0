reset
set terminal pngcairo noenhanced size 1280,800 font 'sans,11'
set output 'density.png'
set title "Frame time against light count at constant light density: atrium, 1920x1080\nNVIDIA H200, NVIDIA 580.159.04, commit 72046008e4da"
set xlabel "lights in the scene (its own plus the random ones added)"
set ylabel "GPU frame time, ms (median; bars: min to max)"
set logscale xy
set format x '%.0f'
set xrange [907.2:5243017.5]
set xtics (1134, 4206, 16494, 65646, 262254, 1048686, 4194414)
set grid xtics ytics mytics
set key top left box opaque
plot 'density.dat' index 0 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 1 title "lll/compute"
reset
set terminal pngcairo noenhanced size 1280,800 font 'sans,11'
set output 'density-passes.png'
set title "Light data and shading against light count at constant light density: atrium, 1920x1080\nNVIDIA H200, NVIDIA 580.159.04, commit 72046008e4da"
set xlabel "lights in the scene (its own plus the random ones added)"
set ylabel "GPU ms (median): the technique's own passes dashed, shade-opaque + glass solid"
set logscale xy
set format x '%.0f'
set xrange [907.2:5243017.5]
set xtics (1134, 4206, 16494, 65646, 262254, 1048686, 4194414)
set grid xtics ytics mytics
set key top left box opaque
plot 'density-passes.dat' index 0 using 1:2:3:4 with linespoints dt 2 lw 2 pt 6 lc 1 title "lll/compute: own passes", 'density-passes.dat' index 1 using 1:2:3:4 with linespoints lw 2 pt 7 lc 1 title "lll/compute: shade-opaque + glass"
reset
set terminal pngcairo noenhanced size 1280,800 font 'sans,11'
set output 'density-memory.png'
set title "Lighting-data memory against light count at constant light density: atrium, 1920x1080\nNVIDIA H200, NVIDIA 580.159.04, commit 72046008e4da"
set xlabel "lights in the scene (its own plus the random ones added)"
set ylabel "GPU memory of the lighting data, MiB (depth + the technique's buffers)"
set logscale xy
set format x '%.0f'
set xrange [907.2:5243017.5]
set xtics (1134, 4206, 16494, 65646, 262254, 1048686, 4194414)
set grid xtics ytics mytics
set key top left box opaque
plot 'density-memory.dat' index 0 using 1:2:3:4 with yerrorlines lw 2 pt 7 lc 1 title "lll/compute"
