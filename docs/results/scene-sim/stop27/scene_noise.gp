# scene_noise: run `gnuplot scene_noise.gp` in this folder
set terminal pngcairo size 640,420 font 'sans,11' noenhanced
set output 'scene_noise.png'
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
set xrange [0.016:0.104]
set datafile separator ','
set key bottom left
set grid
set title 'scene: 20 tiles per point, noise swept (others at the reference)'
set xlabel 'range noise sigma (m)'
set ylabel '% of database vehicles'
set yrange [0:105]
set y2label 'false alarms per tile'
set y2range [0:1]
set y2tics
set ytics nomirror
plot 'plot_noise.csv' using 1:2 with linespoints ls 1 title 'found', '' using 1:3 with linespoints ls 2 title 'ranked right first', '' using 1:4 with linespoints ls 3 title 'confident and right', '' using 1:5 axes x1y2 with linespoints ls 4 title 'false alarms per tile'
