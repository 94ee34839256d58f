# build_cost: run `gnuplot build_cost.gp` in this folder
set terminal pngcairo size 1100,480 font 'sans,11' noenhanced
set output 'build_cost.png'
set fit quiet
set fit logfile '/dev/null'
set style line 1 lc rgb '#1f5fa8' lw 2 pt 7 ps 1.0
set style line 2 lc rgb '#c8281e' lw 2 pt 5 ps 0.9
set style line 3 lc rgb '#2e8b3a' lw 2 pt 9 ps 1.1
set style line 4 lc rgb '#7f3fbf' lw 2 pt 11 ps 1.0
set style line 5 lc rgb '#e08a00' lw 2 pt 13 ps 1.0
set style line 6 lc rgb '#555555' lw 2 pt 3 ps 1.0
set style line 9 lc rgb '#999999' lw 1 dt 2
set grid lc rgb '#dddddd'
set datafile separator ','
set datafile columnheaders
set key top left
set xlabel 'features in the database'
set xrange [0:*]
set yrange [0:*]
set multiplot layout 1,2 title 'Database build (in memory, after the model scans)'
set title 'build time'
set ylabel 's'
f(x) = a*x + c
fit f(x) 'build.csv' using 2:3 via a, c
plot 'build.csv' using 2:3 with linespoints ls 1 title 'features + grids + LSH', f(x) ls 9 title 'least-squares line'
set title 'blob size'
set ylabel 'MB'
plot 'build.csv' using 2:($5/1e+06) with linespoints ls 2 title 'blob', x*0.00016 ls 9 title '160 B/feature'
unset multiplot
