# gnuplot script written by gjk_study (chapter 07): gnuplot gjk-boolean-warm.gp
set terminal pngcairo size 1500,1000 font 'sans,10'
set output 'gjk-boolean-warm.png'
set datafile separator ','
set termoption noenhanced
set multiplot title "GJK, boolean queries, warm-started: wrong-answer rate against median time per query, one point per method, one panel per shape"
set logscale xy
set grid
set format y '%.0e'
unset key
set xlabel 'median time per query (ns)' offset 0,0.3
set ylabel 'wrong answers / judged queries'
set lmargin at screen 0.0466667
set rmargin at screen 0.323333
set bmargin at screen 0.585
set tmargin at screen 0.922
set xtics ('50' 50, '100' 100, '200' 200, '500' 500, '1000' 1000, '2000' 2000)
set xrange [38.0963:3924.91]
set yrange [2e-05:3]
set title 'box (4096 queries)' offset 0,-0.6
plot 'gjk-boolean-warm.csv' skip 1 using ($1==0 ? $6 : NaN):13:($16/1.04-$6):($17-$13) with vectors nohead lc rgb '#bbbbbb' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==0 ? $6 : NaN):13 with points pt 7 ps 1.6 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==0 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==1 ? $6 : NaN):13 with points pt 6 ps 1.6 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==1 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==2 ? $6 : NaN):13 with points pt 5 ps 1.6 lw 1.5 lc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==2 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==3 ? $6 : NaN):13 with points pt 4 ps 1.6 lw 1.5 lc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==3 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==4 ? $6 : NaN):13 with points pt 9 ps 1.6 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==4 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==5 ? $6 : NaN):13 with points pt 11 ps 1.6 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==5 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==6 ? $6 : NaN):13 with points pt 15 ps 1.6 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==6 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==7 ? $6 : NaN):13 with points pt 13 ps 1.6 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==7 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#17becf' notitle
set lmargin at screen 0.38
set rmargin at screen 0.656667
set bmargin at screen 0.585
set tmargin at screen 0.922
set xtics ('50' 50, '100' 100, '200' 200, '500' 500)
set xrange [32.831:523.793]
set yrange [2e-05:3]
set title 'sphere (4096 queries)' offset 0,-0.6
plot 'gjk-boolean-warm.csv' skip 1 using ($1==1 ? $6 : NaN):13:($16/1.04-$6):($17-$13) with vectors nohead lc rgb '#bbbbbb' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==0 ? $6 : NaN):13 with points pt 7 ps 1.6 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==0 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==1 ? $6 : NaN):13 with points pt 6 ps 1.6 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==1 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==2 ? $6 : NaN):13 with points pt 5 ps 1.6 lw 1.5 lc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==2 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==3 ? $6 : NaN):13 with points pt 4 ps 1.6 lw 1.5 lc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==3 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==4 ? $6 : NaN):13 with points pt 9 ps 1.6 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==4 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==5 ? $6 : NaN):13 with points pt 11 ps 1.6 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==5 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==6 ? $6 : NaN):13 with points pt 15 ps 1.6 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==6 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==7 ? $6 : NaN):13 with points pt 13 ps 1.6 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==7 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#17becf' notitle
set lmargin at screen 0.713333
set rmargin at screen 0.99
set bmargin at screen 0.585
set tmargin at screen 0.922
set xtics ('100' 100, '1000' 1000, '10000' 10000)
set xrange [45.6183:15612.8]
set yrange [2e-05:3]
set title 'capsule (4096 queries)' offset 0,-0.6
plot 'gjk-boolean-warm.csv' skip 1 using ($1==2 ? $6 : NaN):13:($16/1.04-$6):($17-$13) with vectors nohead lc rgb '#bbbbbb' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==0 ? $6 : NaN):13 with points pt 7 ps 1.6 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==0 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==1 ? $6 : NaN):13 with points pt 6 ps 1.6 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==1 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==2 ? $6 : NaN):13 with points pt 5 ps 1.6 lw 1.5 lc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==2 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==3 ? $6 : NaN):13 with points pt 4 ps 1.6 lw 1.5 lc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==3 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==4 ? $6 : NaN):13 with points pt 9 ps 1.6 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==4 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==5 ? $6 : NaN):13 with points pt 11 ps 1.6 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==5 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==6 ? $6 : NaN):13 with points pt 15 ps 1.6 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==6 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==7 ? $6 : NaN):13 with points pt 13 ps 1.6 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==7 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#17becf' notitle
set lmargin at screen 0.0466667
set rmargin at screen 0.323333
set bmargin at screen 0.17
set tmargin at screen 0.507
set xtics ('100' 100, '200' 200, '500' 500, '1000' 1000, '2000' 2000, '5000' 5000)
set xrange [52.742:6961.32]
set yrange [2e-05:3]
set title 'polytope12 (4096 queries)' offset 0,-0.6
plot 'gjk-boolean-warm.csv' skip 1 using ($1==3 ? $6 : NaN):13:($16/1.04-$6):($17-$13) with vectors nohead lc rgb '#bbbbbb' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==0 ? $6 : NaN):13 with points pt 7 ps 1.6 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==0 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==1 ? $6 : NaN):13 with points pt 6 ps 1.6 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==1 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==2 ? $6 : NaN):13 with points pt 5 ps 1.6 lw 1.5 lc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==2 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==3 ? $6 : NaN):13 with points pt 4 ps 1.6 lw 1.5 lc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==3 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==4 ? $6 : NaN):13 with points pt 9 ps 1.6 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==4 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==5 ? $6 : NaN):13 with points pt 11 ps 1.6 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==5 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==6 ? $6 : NaN):13 with points pt 15 ps 1.6 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==6 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==7 ? $6 : NaN):13 with points pt 13 ps 1.6 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==7 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#17becf' notitle
set lmargin at screen 0.38
set rmargin at screen 0.656667
set bmargin at screen 0.17
set tmargin at screen 0.507
set xtics ('100' 100, '1000' 1000, '10000' 10000, '100000' 100000)
set xrange [54.9543:116746]
set yrange [2e-05:3]
set title 'polytope100 (4096 queries)' offset 0,-0.6
plot 'gjk-boolean-warm.csv' skip 1 using ($1==4 ? $6 : NaN):13:($16/1.04-$6):($17-$13) with vectors nohead lc rgb '#bbbbbb' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==0 ? $6 : NaN):13 with points pt 7 ps 1.6 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==0 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==1 ? $6 : NaN):13 with points pt 6 ps 1.6 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==1 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==2 ? $6 : NaN):13 with points pt 5 ps 1.6 lw 1.5 lc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==2 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==3 ? $6 : NaN):13 with points pt 4 ps 1.6 lw 1.5 lc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==3 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==4 ? $6 : NaN):13 with points pt 9 ps 1.6 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==4 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==5 ? $6 : NaN):13 with points pt 11 ps 1.6 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==5 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==6 ? $6 : NaN):13 with points pt 15 ps 1.6 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==6 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==7 ? $6 : NaN):13 with points pt 13 ps 1.6 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==7 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#17becf' notitle
set lmargin at screen 0.713333
set rmargin at screen 0.99
set bmargin at screen 0.17
set tmargin at screen 0.507
set xtics ('100' 100, '1000' 1000, '10000' 10000, '100000' 100000, '1e+06' 1e+06)
set xrange [61.1488:1.50242e+06]
set yrange [2e-05:3]
set title 'polytope1000 (4096 queries)' offset 0,-0.6
plot 'gjk-boolean-warm.csv' skip 1 using ($1==5 ? $6 : NaN):13:($16/1.04-$6):($17-$13) with vectors nohead lc rgb '#bbbbbb' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==0 ? $6 : NaN):13 with points pt 7 ps 1.6 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==0 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==1 ? $6 : NaN):13 with points pt 6 ps 1.6 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==1 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==2 ? $6 : NaN):13 with points pt 5 ps 1.6 lw 1.5 lc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==2 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==3 ? $6 : NaN):13 with points pt 4 ps 1.6 lw 1.5 lc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==3 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==4 ? $6 : NaN):13 with points pt 9 ps 1.6 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==4 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==5 ? $6 : NaN):13 with points pt 11 ps 1.6 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==5 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==6 ? $6 : NaN):13 with points pt 15 ps 1.6 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==6 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==7 ? $6 : NaN):13 with points pt 13 ps 1.6 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==7 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#17becf' notitle
set origin 0,0
set size 1,0.12
set lmargin 0
set rmargin 0
set tmargin 0
set bmargin 0
unset title
unset logscale
unset border
unset tics
unset grid
unset xlabel
unset ylabel
set xrange [0:1]
set yrange [0:1]
set key at screen 0.5,0.105 center top horizontal maxrows 1 width 2 samplen 1 font ',10'
set label 1 "A wrong-answer rate of 0 is drawn at 1e-04; a label says how many answers were wrong. A label says when a method gave no answer on some queries." at screen 0.5,0.04 center font ',10'
plot NaN with points pt 7 ps 1.6 lc rgb '#08306b' title 'ours-double', NaN with points pt 6 ps 1.6 lc rgb '#4292c6' title 'ours-float', NaN with points pt 5 ps 1.6 lc rgb '#ff7f0e' title 'ccd-gjk', NaN with points pt 4 ps 1.6 lc rgb '#8c564b' title 'ccd-mpr', NaN with points pt 9 ps 1.6 lc rgb '#d62728' title 'fcl-libccd', NaN with points pt 11 ps 1.6 lc rgb '#e377c2' title 'fcl-indep', NaN with points pt 15 ps 1.6 lc rgb '#2ca02c' title 'bullet-gjk-dist', NaN with points pt 13 ps 1.6 lc rgb '#17becf' title 'ours-curved'
unset multiplot
