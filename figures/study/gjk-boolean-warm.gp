# gnuplot script written by gjk_study (chapter 09): gnuplot gjk-boolean-warm.gp
set terminal pngcairo size 1500,1000 font 'sans,10'
set output 'gjk-boolean-warm.png'
set datafile separator ','
set termoption noenhanced
set multiplot title "GJK, boolean queries, warm-started: median time per query (point) and 99th percentile (whisker) per method, one panel per shape; wrong answers counted at the right"
set logscale x
set grid xtics
unset key
set xlabel 'time per query (ns)' offset 0,0.3
set lmargin at screen 0.0733333
set rmargin at screen 0.323333
set bmargin at screen 0.585
set tmargin at screen 0.922
set xtics ('100' 100, '1000' 1000)
set xrange [25.0429:52552.8]
set yrange [7.6:-0.6]
set ytics ('ours-double' 0, 'ours-float' 1, 'ccd-gjk' 2, 'ccd-mpr' 3, 'fcl-libccd' 4, 'fcl-indep' 5, 'bullet-gjk-dist' 6) font ',9'
set title 'box (4096 queries)' offset 0,-0.6
plot 'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==0 ? $6 : NaN):3:6:7 with xerrorbars pt 7 ps 1.5 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==1 ? $6 : NaN):3:6:7 with xerrorbars pt 6 ps 1.5 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==2 ? $6 : NaN):3:6:7 with xerrorbars pt 5 ps 1.5 lw 1.5 lc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==3 ? $6 : NaN):3:6:7 with xerrorbars pt 4 ps 1.5 lw 1.5 lc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==4 ? $6 : NaN):3:6:7 with xerrorbars pt 9 ps 1.5 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==5 ? $6 : NaN):3:6:7 with xerrorbars pt 11 ps 1.5 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==6 ? $6 : NaN):3:6:7 with xerrorbars pt 15 ps 1.5 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $3==7 ? $6 : NaN):3:6:7 with xerrorbars pt 13 ps 1.5 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && $11==0 && $12==0 ? 5865.63 : NaN):3:(sprintf('%d/%d wrong', $11, $10)) with labels left font ',9' tc rgb '#777777' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==0 && ($11>0 || $12>0) ? 5865.63 : NaN):3:(sprintf('%d/%d wrong%s', $11, $10, $12>0 ? sprintf(', %d no answer', $12) : '')) with labels left font ',9:Bold' tc rgb '#c00000' notitle
set lmargin at screen 0.406667
set rmargin at screen 0.656667
set bmargin at screen 0.585
set tmargin at screen 0.922
set xtics ('50' 50, '100' 100, '200' 200, '500' 500)
set xrange [32.6357:2955.5]
set yrange [7.6:-0.6]
set ytics ('ours-double' 0, 'ours-float' 1, 'ours-curved' 7, 'ccd-gjk' 2, 'ccd-mpr' 3, 'fcl-libccd' 4, 'fcl-indep' 5, 'bullet-gjk-dist' 6) font ',9'
set title 'sphere (4096 queries)' offset 0,-0.6
plot 'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==0 ? $6 : NaN):3:6:7 with xerrorbars pt 7 ps 1.5 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==1 ? $6 : NaN):3:6:7 with xerrorbars pt 6 ps 1.5 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==2 ? $6 : NaN):3:6:7 with xerrorbars pt 5 ps 1.5 lw 1.5 lc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==3 ? $6 : NaN):3:6:7 with xerrorbars pt 4 ps 1.5 lw 1.5 lc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==4 ? $6 : NaN):3:6:7 with xerrorbars pt 9 ps 1.5 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==5 ? $6 : NaN):3:6:7 with xerrorbars pt 11 ps 1.5 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==6 ? $6 : NaN):3:6:7 with xerrorbars pt 15 ps 1.5 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $3==7 ? $6 : NaN):3:6:7 with xerrorbars pt 13 ps 1.5 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && $11==0 && $12==0 ? 812.161 : NaN):3:(sprintf('%d/%d wrong', $11, $10)) with labels left font ',9' tc rgb '#777777' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==1 && ($11>0 || $12>0) ? 812.161 : NaN):3:(sprintf('%d/%d wrong%s', $11, $10, $12>0 ? sprintf(', %d no answer', $12) : '')) with labels left font ',9:Bold' tc rgb '#c00000' notitle
set lmargin at screen 0.74
set rmargin at screen 0.99
set bmargin at screen 0.585
set tmargin at screen 0.922
set xtics ('100' 100, '1000' 1000)
set xrange [43.7929:121847]
set yrange [7.6:-0.6]
set ytics ('ours-double' 0, 'ours-float' 1, 'ours-curved' 7, 'ccd-gjk' 2, 'ccd-mpr' 3, 'fcl-libccd' 4, 'fcl-indep' 5, 'bullet-gjk-dist' 6) font ',9'
set title 'capsule (4096 queries)' offset 0,-0.6
plot 'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==0 ? $6 : NaN):3:6:7 with xerrorbars pt 7 ps 1.5 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==1 ? $6 : NaN):3:6:7 with xerrorbars pt 6 ps 1.5 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==2 ? $6 : NaN):3:6:7 with xerrorbars pt 5 ps 1.5 lw 1.5 lc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==3 ? $6 : NaN):3:6:7 with xerrorbars pt 4 ps 1.5 lw 1.5 lc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==4 ? $6 : NaN):3:6:7 with xerrorbars pt 9 ps 1.5 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==5 ? $6 : NaN):3:6:7 with xerrorbars pt 11 ps 1.5 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==6 ? $6 : NaN):3:6:7 with xerrorbars pt 15 ps 1.5 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $3==7 ? $6 : NaN):3:6:7 with xerrorbars pt 13 ps 1.5 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && $11==0 && $12==0 ? 12543.5 : NaN):3:(sprintf('%d/%d wrong', $11, $10)) with labels left font ',9' tc rgb '#777777' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==2 && ($11>0 || $12>0) ? 12543.5 : NaN):3:(sprintf('%d/%d wrong%s', $11, $10, $12>0 ? sprintf(', %d no answer', $12) : '')) with labels left font ',9:Bold' tc rgb '#c00000' notitle
set lmargin at screen 0.0733333
set rmargin at screen 0.323333
set bmargin at screen 0.17
set tmargin at screen 0.507
set xtics ('100' 100, '1000' 1000)
set xrange [37.1:61505.9]
set yrange [7.6:-0.6]
set ytics ('ours-double' 0, 'ours-float' 1, 'ccd-gjk' 2, 'ccd-mpr' 3, 'fcl-libccd' 4, 'fcl-indep' 5, 'bullet-gjk-dist' 6) font ',9'
set title 'polytope12 (4096 queries)' offset 0,-0.6
plot 'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==0 ? $6 : NaN):3:6:7 with xerrorbars pt 7 ps 1.5 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==1 ? $6 : NaN):3:6:7 with xerrorbars pt 6 ps 1.5 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==2 ? $6 : NaN):3:6:7 with xerrorbars pt 5 ps 1.5 lw 1.5 lc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==3 ? $6 : NaN):3:6:7 with xerrorbars pt 4 ps 1.5 lw 1.5 lc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==4 ? $6 : NaN):3:6:7 with xerrorbars pt 9 ps 1.5 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==5 ? $6 : NaN):3:6:7 with xerrorbars pt 11 ps 1.5 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==6 ? $6 : NaN):3:6:7 with xerrorbars pt 15 ps 1.5 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $3==7 ? $6 : NaN):3:6:7 with xerrorbars pt 13 ps 1.5 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && $11==0 && $12==0 ? 7344.82 : NaN):3:(sprintf('%d/%d wrong', $11, $10)) with labels left font ',9' tc rgb '#777777' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==3 && ($11>0 || $12>0) ? 7344.82 : NaN):3:(sprintf('%d/%d wrong%s', $11, $10, $12>0 ? sprintf(', %d no answer', $12) : '')) with labels left font ',9:Bold' tc rgb '#c00000' notitle
set lmargin at screen 0.406667
set rmargin at screen 0.656667
set bmargin at screen 0.17
set tmargin at screen 0.507
set xtics ('100' 100, '1000' 1000, '10000' 10000, '100000' 100000)
set xrange [38.8857:3.51361e+07]
set yrange [7.6:-0.6]
set ytics ('ours-double' 0, 'ours-float' 1, 'ccd-gjk' 2, 'ccd-mpr' 3, 'fcl-libccd' 4, 'fcl-indep' 5, 'bullet-gjk-dist' 6) font ',9'
set title 'polytope100 (4096 queries)' offset 0,-0.6
plot 'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==0 ? $6 : NaN):3:6:7 with xerrorbars pt 7 ps 1.5 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==1 ? $6 : NaN):3:6:7 with xerrorbars pt 6 ps 1.5 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==2 ? $6 : NaN):3:6:7 with xerrorbars pt 5 ps 1.5 lw 1.5 lc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==3 ? $6 : NaN):3:6:7 with xerrorbars pt 4 ps 1.5 lw 1.5 lc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==4 ? $6 : NaN):3:6:7 with xerrorbars pt 9 ps 1.5 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==5 ? $6 : NaN):3:6:7 with xerrorbars pt 11 ps 1.5 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==6 ? $6 : NaN):3:6:7 with xerrorbars pt 15 ps 1.5 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $3==7 ? $6 : NaN):3:6:7 with xerrorbars pt 13 ps 1.5 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && $11==0 && $12==0 ? 689251 : NaN):3:(sprintf('%d/%d wrong', $11, $10)) with labels left font ',9' tc rgb '#777777' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==4 && ($11>0 || $12>0) ? 689251 : NaN):3:(sprintf('%d/%d wrong%s', $11, $10, $12>0 ? sprintf(', %d no answer', $12) : '')) with labels left font ',9:Bold' tc rgb '#c00000' notitle
set lmargin at screen 0.74
set rmargin at screen 0.99
set bmargin at screen 0.17
set tmargin at screen 0.507
set xtics ('100' 100, '1000' 1000, '10000' 10000, '100000' 100000)
set xrange [46.4714:5.78901e+07]
set yrange [7.6:-0.6]
set ytics ('ours-double' 0, 'ours-float' 1, 'ccd-gjk' 2, 'ccd-mpr' 3, 'fcl-libccd' 4, 'fcl-indep' 5, 'bullet-gjk-dist' 6) font ',9'
set title 'polytope1000 (4096 queries)' offset 0,-0.6
plot 'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==0 ? $6 : NaN):3:6:7 with xerrorbars pt 7 ps 1.5 lw 1.5 lc rgb '#08306b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==1 ? $6 : NaN):3:6:7 with xerrorbars pt 6 ps 1.5 lw 1.5 lc rgb '#4292c6' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==2 ? $6 : NaN):3:6:7 with xerrorbars pt 5 ps 1.5 lw 1.5 lc rgb '#ff7f0e' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==3 ? $6 : NaN):3:6:7 with xerrorbars pt 4 ps 1.5 lw 1.5 lc rgb '#8c564b' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==4 ? $6 : NaN):3:6:7 with xerrorbars pt 9 ps 1.5 lw 1.5 lc rgb '#d62728' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==5 ? $6 : NaN):3:6:7 with xerrorbars pt 11 ps 1.5 lw 1.5 lc rgb '#e377c2' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==6 ? $6 : NaN):3:6:7 with xerrorbars pt 15 ps 1.5 lw 1.5 lc rgb '#2ca02c' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $3==7 ? $6 : NaN):3:6:7 with xerrorbars pt 13 ps 1.5 lw 1.5 lc rgb '#17becf' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && $11==0 && $12==0 ? 1.03574e+06 : NaN):3:(sprintf('%d/%d wrong', $11, $10)) with labels left font ',9' tc rgb '#777777' notitle, \
     'gjk-boolean-warm.csv' skip 1 using ($1==5 && ($11>0 || $12>0) ? 1.03574e+06 : NaN):3:(sprintf('%d/%d wrong%s', $11, $10, $12>0 ? sprintf(', %d no answer', $12) : '')) with labels left font ',9:Bold' tc rgb '#c00000' notitle
set label 1 "Times over batches of queries timed together. Judged: the queries whose reference distance is 0 or above 5e-04 (closer pairs are touching within the methods' tolerances)." at screen 0.5,0.06 center font ',10'
unset border
unset tics
unset grid
unset xlabel
unset title
unset logscale
set xrange [0:1]
set yrange [0:1]
plot NaN notitle
unset multiplot
