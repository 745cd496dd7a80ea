# gnuplot script written by gjk_study (chapter 09): gnuplot gjk-distance-cold.gp
set terminal pngcairo size 1500,1000 font 'sans,10'
set output 'gjk-distance-cold.png'
set datafile separator ','
set termoption noenhanced
set multiplot title "GJK, distance queries, cold: error against median time per query, one point per method, one panel per shape"
set logscale xy
set grid
set format y '%.0e'
unset key
set xlabel 'median time per query (ns)' offset 0,0.3
set ylabel "|d - d_ref| (the shapes' length unit)"
set lmargin at screen 0.0466667
set rmargin at screen 0.323333
set bmargin at screen 0.585
set tmargin at screen 0.922
set xtics ('500' 500, '1000' 1000, '2000' 2000)
set xrange [432.909:2409.38]
set yrange [2e-19:10]
set title 'box (256 queries)' offset 0,-0.6
plot 'gjk-distance-cold.csv' skip 1 using ($1==0 ? $6 : NaN):13:($16/1.04-$6):($17-$13) with vectors nohead lc rgb '#bbbbbb' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==0 && $3==0 ? $6 : NaN):13:13:14 with yerrorbars pt 7 ps 1.6 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==0 && $3==0 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#08306b' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==0 && $3==1 ? $6 : NaN):13:13:14 with yerrorbars pt 6 ps 1.6 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==0 && $3==1 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#4292c6' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==0 && $3==2 ? $6 : NaN):13:13:14 with yerrorbars pt 9 ps 1.6 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==0 && $3==2 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#d62728' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==0 && $3==3 ? $6 : NaN):13:13:14 with yerrorbars pt 11 ps 1.6 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==0 && $3==3 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#e377c2' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==0 && $3==4 ? $6 : NaN):13:13:14 with yerrorbars pt 15 ps 1.6 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==0 && $3==4 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#2ca02c' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==0 && $3==5 ? $6 : NaN):13:13:14 with yerrorbars pt 13 ps 1.6 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==0 && $3==5 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#17becf' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==0 && $12 > 0 ? $6 : NaN):13 with points pt 2 ps 2.6 lw 2.5 lc rgb '#000000' notitle
set lmargin at screen 0.38
set rmargin at screen 0.656667
set bmargin at screen 0.585
set tmargin at screen 0.922
set xtics ('50' 50, '100' 100, '200' 200)
set xrange [27.4754:422.031]
set yrange [2e-19:10]
set title 'sphere (256 queries)' offset 0,-0.6
plot 'gjk-distance-cold.csv' skip 1 using ($1==1 ? $6 : NaN):13:($16/1.04-$6):($17-$13) with vectors nohead lc rgb '#bbbbbb' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==1 && $3==0 ? $6 : NaN):13:13:14 with yerrorbars pt 7 ps 1.6 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==1 && $3==0 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#08306b' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==1 && $3==1 ? $6 : NaN):13:13:14 with yerrorbars pt 6 ps 1.6 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==1 && $3==1 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#4292c6' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==1 && $3==2 ? $6 : NaN):13:13:14 with yerrorbars pt 9 ps 1.6 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==1 && $3==2 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#d62728' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==1 && $3==3 ? $6 : NaN):13:13:14 with yerrorbars pt 11 ps 1.6 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==1 && $3==3 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#e377c2' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==1 && $3==4 ? $6 : NaN):13:13:14 with yerrorbars pt 15 ps 1.6 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==1 && $3==4 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#2ca02c' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==1 && $3==5 ? $6 : NaN):13:13:14 with yerrorbars pt 13 ps 1.6 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==1 && $3==5 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#17becf' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==1 && $12 > 0 ? $6 : NaN):13 with points pt 2 ps 2.6 lw 2.5 lc rgb '#000000' notitle
set lmargin at screen 0.713333
set rmargin at screen 0.99
set bmargin at screen 0.585
set tmargin at screen 0.922
set xtics ('100' 100, '1000' 1000, '10000' 10000)
set xrange [38.1441:37505.1]
set yrange [2e-19:10]
set title 'capsule (256 queries)' offset 0,-0.6
plot 'gjk-distance-cold.csv' skip 1 using ($1==2 ? $6 : NaN):13:($16/1.04-$6):($17-$13) with vectors nohead lc rgb '#bbbbbb' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==2 && $3==0 ? $6 : NaN):13:13:14 with yerrorbars pt 7 ps 1.6 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==2 && $3==0 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#08306b' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==2 && $3==1 ? $6 : NaN):13:13:14 with yerrorbars pt 6 ps 1.6 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==2 && $3==1 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#4292c6' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==2 && $3==2 ? $6 : NaN):13:13:14 with yerrorbars pt 9 ps 1.6 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==2 && $3==2 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#d62728' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==2 && $3==3 ? $6 : NaN):13:13:14 with yerrorbars pt 11 ps 1.6 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==2 && $3==3 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#e377c2' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==2 && $3==4 ? $6 : NaN):13:13:14 with yerrorbars pt 15 ps 1.6 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==2 && $3==4 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#2ca02c' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==2 && $3==5 ? $6 : NaN):13:13:14 with yerrorbars pt 13 ps 1.6 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==2 && $3==5 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#17becf' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==2 && $12 > 0 ? $6 : NaN):13 with points pt 2 ps 2.6 lw 2.5 lc rgb '#000000' notitle
set lmargin at screen 0.0466667
set rmargin at screen 0.323333
set bmargin at screen 0.17
set tmargin at screen 0.507
set xtics ('1000' 1000, '2000' 2000)
set xrange [679.77:3783.3]
set yrange [2e-19:10]
set title 'polytope12 (256 queries)' offset 0,-0.6
plot 'gjk-distance-cold.csv' skip 1 using ($1==3 ? $6 : NaN):13:($16/1.04-$6):($17-$13) with vectors nohead lc rgb '#bbbbbb' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==3 && $3==0 ? $6 : NaN):13:13:14 with yerrorbars pt 7 ps 1.6 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==3 && $3==0 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#08306b' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==3 && $3==1 ? $6 : NaN):13:13:14 with yerrorbars pt 6 ps 1.6 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==3 && $3==1 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#4292c6' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==3 && $3==2 ? $6 : NaN):13:13:14 with yerrorbars pt 9 ps 1.6 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==3 && $3==2 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#d62728' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==3 && $3==3 ? $6 : NaN):13:13:14 with yerrorbars pt 11 ps 1.6 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==3 && $3==3 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#e377c2' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==3 && $3==4 ? $6 : NaN):13:13:14 with yerrorbars pt 15 ps 1.6 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==3 && $3==4 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#2ca02c' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==3 && $3==5 ? $6 : NaN):13:13:14 with yerrorbars pt 13 ps 1.6 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==3 && $3==5 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#17becf' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==3 && $12 > 0 ? $6 : NaN):13 with points pt 2 ps 2.6 lw 2.5 lc rgb '#000000' notitle
set lmargin at screen 0.38
set rmargin at screen 0.656667
set bmargin at screen 0.17
set tmargin at screen 0.507
set xtics ('2000' 2000, '5000' 5000, '10000' 10000, '20000' 20000)
set xrange [1529.87:25274]
set yrange [2e-19:10]
set title 'polytope100 (256 queries)' offset 0,-0.6
plot 'gjk-distance-cold.csv' skip 1 using ($1==4 ? $6 : NaN):13:($16/1.04-$6):($17-$13) with vectors nohead lc rgb '#bbbbbb' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==4 && $3==0 ? $6 : NaN):13:13:14 with yerrorbars pt 7 ps 1.6 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==4 && $3==0 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#08306b' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==4 && $3==1 ? $6 : NaN):13:13:14 with yerrorbars pt 6 ps 1.6 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==4 && $3==1 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#4292c6' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==4 && $3==2 ? $6 : NaN):13:13:14 with yerrorbars pt 9 ps 1.6 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==4 && $3==2 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#d62728' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==4 && $3==3 ? $6 : NaN):13:13:14 with yerrorbars pt 11 ps 1.6 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==4 && $3==3 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#e377c2' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==4 && $3==4 ? $6 : NaN):13:13:14 with yerrorbars pt 15 ps 1.6 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==4 && $3==4 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#2ca02c' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==4 && $3==5 ? $6 : NaN):13:13:14 with yerrorbars pt 13 ps 1.6 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==4 && $3==5 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#17becf' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==4 && $12 > 0 ? $6 : NaN):13 with points pt 2 ps 2.6 lw 2.5 lc rgb '#000000' notitle
set lmargin at screen 0.713333
set rmargin at screen 0.99
set bmargin at screen 0.17
set tmargin at screen 0.507
set xtics ('5000' 5000, '10000' 10000, '20000' 20000, '50000' 50000, '100000' 100000, '200000' 200000)
set xrange [3463.98:327404]
set yrange [2e-19:10]
set title 'polytope1000 (256 queries)' offset 0,-0.6
plot 'gjk-distance-cold.csv' skip 1 using ($1==5 ? $6 : NaN):13:($16/1.04-$6):($17-$13) with vectors nohead lc rgb '#bbbbbb' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==5 && $3==0 ? $6 : NaN):13:13:14 with yerrorbars pt 7 ps 1.6 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==5 && $3==0 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#08306b' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==5 && $3==1 ? $6 : NaN):13:13:14 with yerrorbars pt 6 ps 1.6 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==5 && $3==1 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#4292c6' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==5 && $3==2 ? $6 : NaN):13:13:14 with yerrorbars pt 9 ps 1.6 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==5 && $3==2 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#d62728' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==5 && $3==3 ? $6 : NaN):13:13:14 with yerrorbars pt 11 ps 1.6 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==5 && $3==3 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#e377c2' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==5 && $3==4 ? $6 : NaN):13:13:14 with yerrorbars pt 15 ps 1.6 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==5 && $3==4 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#2ca02c' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==5 && $3==5 ? $6 : NaN):13:13:14 with yerrorbars pt 13 ps 1.6 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==5 && $3==5 ? $16 : NaN):17:15 with labels left font ',8' tc rgb '#17becf' notitle, \
     'gjk-distance-cold.csv' skip 1 using ($1==5 && $12 > 0 ? $6 : NaN):13 with points pt 2 ps 2.6 lw 2.5 lc rgb '#000000' notitle
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
set label 1 "An error of 0 is drawn at 1e-18; the point is the median error over the queries, the bar reaches the maximum. A black cross and the label mark a method that gave no answer on some queries." at screen 0.5,0.04 center font ',10'
plot NaN with points pt 7 ps 1.6 lc rgb '#08306b' title 'ours-double', NaN with points pt 6 ps 1.6 lc rgb '#4292c6' title 'ours-float', NaN with points pt 9 ps 1.6 lc rgb '#d62728' title 'fcl-libccd', NaN with points pt 11 ps 1.6 lc rgb '#e377c2' title 'fcl-indep', NaN with points pt 15 ps 1.6 lc rgb '#2ca02c' title 'bullet-gjk', NaN with points pt 13 ps 1.6 lc rgb '#17becf' title 'ours-curved'
unset multiplot
