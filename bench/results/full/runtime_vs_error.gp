set terminal pngcairo size 1200,520 font ",11"
set output 'bench/results/full/runtime_vs_error.png'
set multiplot layout 1,2 title "ricochet bench: run time against error, 7 sweep workloads, median of 7 runs (shared 2-core machine)"
set logscale xy
set grid
set xlabel "ns per sweep query (geometric mean over workloads)"
set ylabel "wrong hit decisions per million (0 at 0.1)"
set key top right
set offsets graph 0.05, graph 0.15, graph 0.12, graph 0.05
names = "lecture-float lecture-double robust exact box2d chipmunk cgal"
plot for [i=1:words(names)] 'bench/results/full/runtime_vs_error.dat' index (i-1) using 2:3 with points pt (4+i) ps 2 lw 2 title word(names, i)
set ylabel "max contact error, uniform + far (ulps of scale; 0 at 0.1)"
plot for [i=1:words(names)] 'bench/results/full/runtime_vs_error.dat' index (i-1) using 2:4 with points pt (4+i) ps 2 lw 2 title word(names, i)
unset multiplot
