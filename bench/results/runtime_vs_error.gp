set terminal pngcairo size 1200,520 font ",11"
set output 'bench/results/runtime_vs_error.png'
set multiplot layout 1,2 title "ricochet bench --quick: run time against error, 7 sweep workloads, median of 5 runs (shared 2-core machine)"
set logscale xy
set grid
set xlabel "ns per sweep query (geometric mean over workloads)"
set ylabel "wrong hit decisions per million queries vs exact (0 drawn at 0.1)"
set key off
set offsets graph 0.05, graph 0.15, graph 0.12, graph 0.05
plot 'bench/results/runtime_vs_error.dat' using 2:3 with points pt 7 ps 1.5, '' using 2:3:1 with labels offset 0,1
set ylabel "max contact point error on uniform + far, ulps (0 drawn at 0.1)"
plot 'bench/results/runtime_vs_error.dat' using 2:4 with points pt 7 ps 1.5, '' using 2:4:1 with labels offset 0,1
unset multiplot
