# gnuplot script written by toi_study (chapter 09): gnuplot toi-screw_w1.5.gp
set terminal pngcairo size 1300,900 font 'sans,10'
set output 'toi-screw_w1.5.png'
set datafile separator ','
set termoption noenhanced
set multiplot title "time of impact, workload screw_w1.5 (120 queries: 80 hits and 40 clear misses by the reference)"
set lmargin at screen 0.08
set rmargin at screen 0.66
set logscale x
set xrange [0.2926:315.9]
set grid
set tmargin at screen 0.93
set bmargin at screen 0.33
set logscale y
set yrange [1e-11:5]
set format y '%.0e'
set format x ''
unset xlabel
set ylabel 'median |t - t_ref|, in units of the interval [t_0, t_1]'
set label 1 'yes/no only: plotted at error 1' at graph 0.01, first 1.6 left font ',8' tc rgb '#777777'
set key at screen 0.675,0.93 left top Left reverse width -4 samplen 3 spacing 1.15 font ',9'
plot 'toi-screw_w1.5.csv' skip 1 using ($1==0 ? $5 : NaN):13 with linespoints lw 2 pt 9 ps 1.3 lc rgb '#1f77b4' dt 1 title "static double (misses 47/0/0 at N=2/N=8/N=32)", \
     'toi-screw_w1.5.csv' skip 1 using ($1==1 ? $5 : NaN):13 with linespoints lw 2 pt 9 ps 1.3 lc rgb '#1f77b4' dt 2 title "static float (0 misses)", \
     'toi-screw_w1.5.csv' skip 1 using ($1==2 ? $5 : NaN):13 with linespoints lw 2 pt 11 ps 1.3 lc rgb '#ff7f0e' dt 1 title "swept double (0 misses)", \
     'toi-screw_w1.5.csv' skip 1 using ($1==3 ? $5 : NaN):13 with linespoints lw 2 pt 11 ps 1.3 lc rgb '#ff7f0e' dt 2 title "swept float (0 misses)", \
     'toi-screw_w1.5.csv' skip 1 using ($1==4 ? $5 : NaN):13 with linespoints lw 2 pt 13 ps 1.3 lc rgb '#2ca02c' dt 1 title "CA double (0 misses)", \
     'toi-screw_w1.5.csv' skip 1 using ($1==5 ? $5 : NaN):13 with linespoints lw 2 pt 13 ps 1.3 lc rgb '#2ca02c' dt 2 title "CA float (0 misses)", \
     'toi-screw_w1.5.csv' skip 1 using ($1==6 ? $5 : NaN):13 with linespoints lw 2 pt 7 ps 1.3 lc rgb '#d62728' dt 1 title "ours double (0 misses)", \
     'toi-screw_w1.5.csv' skip 1 using ($1==7 ? $5 : NaN):13 with linespoints lw 2 pt 7 ps 1.3 lc rgb '#d62728' dt 2 title "ours float (0 misses)", \
     'toi-screw_w1.5.csv' skip 1 using ($1==8 ? $5 : NaN):13 with linespoints lw 2 pt 5 ps 1.3 lc rgb '#9467bd' dt 1 title "certified double (0 misses)", \
     'toi-screw_w1.5.csv' skip 1 using ($1==9 ? $5 : NaN):13 with linespoints lw 2 pt 5 ps 1.3 lc rgb '#9467bd' dt 2 title "certified float (0 misses)", \
     'toi-screw_w1.5.csv' skip 1 using ($1==10 ? $5 : NaN):13 with linespoints lw 2 pt 15 ps 1.3 lc rgb '#8c564b' dt 1 title "FCL naive double (0 misses)", \
     'toi-screw_w1.5.csv' skip 1 using ($1==11 ? $5 : NaN):13 with linespoints lw 2 pt 6 ps 1.3 lc rgb '#e377c2' dt 1 title "FCL CA double (0 misses)", \
     'toi-screw_w1.5.csv' skip 1 using ($1==12 ? $5 : NaN):13 with linespoints lw 2 pt 8 ps 1.3 lc rgb '#555555' dt 1 title "FCL CA indep double (1 misses)", \
     'toi-screw_w1.5.csv' skip 1 using ($1==13 ? $5 : NaN):13 with linespoints lw 2 pt 12 ps 1.3 lc rgb '#a6a600' dt 2 title "Bullet float (0 misses)", \
     'toi-screw_w1.5.csv' skip 1 using ($9 > 0 ? $5 : NaN):13 with points pt 2 ps 2.2 lw 2.5 lc rgb '#000000' title "X: missed some of the reference's hits", \
     'toi-screw_w1.5.csv' skip 1 using 5:13:14 with labels font ',7' offset 0,0.9 notitle
unset label 1
unset key
set tmargin at screen 0.30
set bmargin at screen 0.09
unset logscale y
set yrange [-6.4:80]
set format y '%g%%'
set ytics 40
set format x '%g'
set xlabel 'median time per query (microseconds)'
set ylabel "missed hits (%)"
plot 'toi-screw_w1.5.csv' skip 1 using ($1==0 ? $5 : NaN):($10 > 0 ? 100.0*$9/$10 : NaN) with points pt 9 ps 1.3 lw 1.5 lc rgb '#1f77b4' notitle, \
     'toi-screw_w1.5.csv' skip 1 using ($1==1 ? $5 : NaN):($10 > 0 ? 100.0*$9/$10 : NaN) with points pt 9 ps 1.3 lw 1.5 lc rgb '#1f77b4' notitle, \
     'toi-screw_w1.5.csv' skip 1 using ($1==2 ? $5 : NaN):($10 > 0 ? 100.0*$9/$10 : NaN) with points pt 11 ps 1.3 lw 1.5 lc rgb '#ff7f0e' notitle, \
     'toi-screw_w1.5.csv' skip 1 using ($1==3 ? $5 : NaN):($10 > 0 ? 100.0*$9/$10 : NaN) with points pt 11 ps 1.3 lw 1.5 lc rgb '#ff7f0e' notitle, \
     'toi-screw_w1.5.csv' skip 1 using ($1==4 ? $5 : NaN):($10 > 0 ? 100.0*$9/$10 : NaN) with points pt 13 ps 1.3 lw 1.5 lc rgb '#2ca02c' notitle, \
     'toi-screw_w1.5.csv' skip 1 using ($1==5 ? $5 : NaN):($10 > 0 ? 100.0*$9/$10 : NaN) with points pt 13 ps 1.3 lw 1.5 lc rgb '#2ca02c' notitle, \
     'toi-screw_w1.5.csv' skip 1 using ($1==6 ? $5 : NaN):($10 > 0 ? 100.0*$9/$10 : NaN) with points pt 7 ps 1.3 lw 1.5 lc rgb '#d62728' notitle, \
     'toi-screw_w1.5.csv' skip 1 using ($1==7 ? $5 : NaN):($10 > 0 ? 100.0*$9/$10 : NaN) with points pt 7 ps 1.3 lw 1.5 lc rgb '#d62728' notitle, \
     'toi-screw_w1.5.csv' skip 1 using ($1==8 ? $5 : NaN):($10 > 0 ? 100.0*$9/$10 : NaN) with points pt 5 ps 1.3 lw 1.5 lc rgb '#9467bd' notitle, \
     'toi-screw_w1.5.csv' skip 1 using ($1==9 ? $5 : NaN):($10 > 0 ? 100.0*$9/$10 : NaN) with points pt 5 ps 1.3 lw 1.5 lc rgb '#9467bd' notitle, \
     'toi-screw_w1.5.csv' skip 1 using ($1==10 ? $5 : NaN):($10 > 0 ? 100.0*$9/$10 : NaN) with points pt 15 ps 1.3 lw 1.5 lc rgb '#8c564b' notitle, \
     'toi-screw_w1.5.csv' skip 1 using ($1==11 ? $5 : NaN):($10 > 0 ? 100.0*$9/$10 : NaN) with points pt 6 ps 1.3 lw 1.5 lc rgb '#e377c2' notitle, \
     'toi-screw_w1.5.csv' skip 1 using ($1==12 ? $5 : NaN):($10 > 0 ? 100.0*$9/$10 : NaN) with points pt 8 ps 1.3 lw 1.5 lc rgb '#555555' notitle, \
     'toi-screw_w1.5.csv' skip 1 using ($1==13 ? $5 : NaN):($10 > 0 ? 100.0*$9/$10 : NaN) with points pt 12 ps 1.3 lw 1.5 lc rgb '#a6a600' notitle, \
     'toi-screw_w1.5.csv' skip 1 using ($9 > 0 ? $5 : NaN):(100.0*$9/$10) with points pt 2 ps 2.2 lw 2.5 lc rgb '#000000' notitle
unset multiplot
