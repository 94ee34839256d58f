# hypotheses_per_query: run `gnuplot hypotheses_per_query.gp` in this folder
set terminal pngcairo size 640,480 font 'sans,11' noenhanced
set output 'hypotheses_per_query.png'
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
set xlabel 'models in the database'
set key top left
set logscale xy
set ylabel 'hypotheses verified per query'
set title 'Mean hypotheses per query (SIND verifies none)'
plot 'scaling_wide.csv' using 1:5 with linespoints ls 1 title 'BRAN', 'scaling_wide.csv' using 1:9 with linespoints ls 2 title 'SRAN'
