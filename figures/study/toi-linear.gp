# gnuplot script written by toi_study (chapter 07): gnuplot toi-linear.gp
set terminal pngcairo size 1200,800 font 'sans,10'
set output 'toi-linear.png'
set datafile separator ','
set termoption noenhanced
set logscale xy
set format y '%.0e'
set grid
set xlabel 'median time per query (microseconds)'
set ylabel 'median |t - t_ref| over the hits both report'
set title "time of impact, workload linear (120 queries): error against time; swept test (yes/no only) plotted at error 1" noenhanced
set key outside right top
plot 'toi-linear.csv' skip 1 using ($1==0 ? $5 : NaN):13 with linespoints lw 2 pt 1 lc rgb '#1f77b4' dt 1 title "static double (misses 53/0/0 at N=2/N=8/N=32)", \
     'toi-linear.csv' skip 1 using ($1==1 ? $5 : NaN):13 with linespoints lw 2 pt 2 lc rgb '#1f77b4' dt 2 title "static float (0 misses)", \
     'toi-linear.csv' skip 1 using ($1==2 ? $5 : NaN):13 with linespoints lw 2 pt 3 lc rgb '#ff7f0e' dt 1 title "swept double (0 misses)", \
     'toi-linear.csv' skip 1 using ($1==3 ? $5 : NaN):13 with linespoints lw 2 pt 4 lc rgb '#ff7f0e' dt 2 title "swept float (0 misses)", \
     'toi-linear.csv' skip 1 using ($1==4 ? $5 : NaN):13 with linespoints lw 2 pt 5 lc rgb '#2ca02c' dt 1 title "CA double (0 misses)", \
     'toi-linear.csv' skip 1 using ($1==5 ? $5 : NaN):13 with linespoints lw 2 pt 6 lc rgb '#2ca02c' dt 2 title "CA float (0 misses)", \
     'toi-linear.csv' skip 1 using ($1==6 ? $5 : NaN):13 with linespoints lw 2 pt 7 lc rgb '#d62728' dt 1 title "ours double (0 misses)", \
     'toi-linear.csv' skip 1 using ($1==7 ? $5 : NaN):13 with linespoints lw 2 pt 8 lc rgb '#d62728' dt 2 title "ours float (0 misses)", \
     'toi-linear.csv' skip 1 using ($1==8 ? $5 : NaN):13 with linespoints lw 2 pt 9 lc rgb '#9467bd' dt 1 title "certified double (0 misses)", \
     'toi-linear.csv' skip 1 using ($1==9 ? $5 : NaN):13 with linespoints lw 2 pt 10 lc rgb '#9467bd' dt 2 title "certified float (0 misses)", \
     'toi-linear.csv' skip 1 using ($1==10 ? $5 : NaN):13 with linespoints lw 2 pt 11 lc rgb '#8c564b' dt 1 title "FCL naive double (0 misses)", \
     'toi-linear.csv' skip 1 using ($1==11 ? $5 : NaN):13 with linespoints lw 2 pt 12 lc rgb '#e377c2' dt 1 title "FCL CA double (4 misses)", \
     'toi-linear.csv' skip 1 using ($1==12 ? $5 : NaN):13 with linespoints lw 2 pt 13 lc rgb '#7f7f7f' dt 1 title "FCL CA indep double (0 misses)", \
     'toi-linear.csv' skip 1 using ($1==13 ? $5 : NaN):13 with linespoints lw 2 pt 1 lc rgb '#bcbd22' dt 2 title "Bullet float (0 misses)", \
     'toi-linear.csv' skip 1 using 5:13:14 with labels font ',7' offset 0,0.8 notitle
