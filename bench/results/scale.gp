set terminal pngcairo size 1400,560 font ',11'
set output 'bench/results/scale.png'
set multiplot layout 1,2 title 'ricochet bench scale: ns per ball-frame (one thread, shared machine)'
set logscale xy
set grid
set ylabel 'ns per ball-frame'
set key top left
set xlabel 'walls (10000 balls)'
plot 'bench/results/scale.dat' index 0 with linespoints lw 2 title 'robust+grid', 'bench/results/scale.dat' index 1 with linespoints lw 2 title 'robust+bvh', 'bench/results/scale.dat' index 2 with linespoints lw 2 title 'robust-brute', 'bench/results/scale.dat' index 3 with linespoints lw 2 title 'box2d-2.4.1'
set xlabel 'balls (10000-wall maze)'
plot 'bench/results/scale.dat' index 4 with linespoints lw 2 title 'robust+grid', 'bench/results/scale.dat' index 5 with linespoints lw 2 title 'robust+bvh', 'bench/results/scale.dat' index 6 with linespoints lw 2 title 'robust-brute', 'bench/results/scale.dat' index 7 with linespoints lw 2 title 'box2d-2.4.1'
unset multiplot
