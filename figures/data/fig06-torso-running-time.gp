# gnuplot script written by 08_torso (chapter 08): gnuplot fig06-torso-running-time.gp
set terminal pngcairo size 1200,860 font 'sans,11'
set output '../fig06-torso-running-time.png'
set datafile separator ','
set termoption noenhanced
set xrange [0:6]
set grid ytics lc rgb '#dddddd'
set lmargin at screen 0.08
set rmargin at screen 0.64
set key at screen 0.655, graph 1 left top Left reverse samplen 2 spacing 1.2
set style fill solid 0.9 noborder
set multiplot title "Fig. 6: running time of the torso-plant simulation\n82 bodies (torso/scene.json), float, certified extrusion test, tolerance 0.000345267, 24 frames/s" font ',12'
set tmargin at screen 0.89
set bmargin at screen 0.56
set logscale y
set format y '%g'
set yrange [0.01:100]
set format x ''
set ylabel 'execution / simulation time' offset 1,0
plot 1.000000 with filledcurves y=7.900000 fs transparent solid 0.25 lc rgb '#999999' title 'paper (500 MHz Pentium III): 1.0 to 7.9', \
     7.900000 with lines dt 2 lw 1.5 lc rgb '#777777' notitle, \
     1.000000 with lines lw 2 lc rgb '#000000' title 'real time (execution = simulation)', \
     'fig06-torso-running-time.csv' skip 2 using 1:($6 > 0.01 ? $6 : 0.01) with lines lw 2 lc rgb '#e15759' title 'ours: every part (the top of the stack below)'
unset logscale y
set format x '%g'
set tmargin at screen 0.50
set bmargin at screen 0.08
set yrange [0:10.0724]
set format y '%g'
set ylabel 'execution / simulation time (linear: the parts)' offset 1,0
set xlabel 'simulated time (s)'
plot 'fig06-torso-running-time.csv' skip 2 using 1:5:6 with filledcurves lc rgb '#b07aa1' title 'Timewarp ordering', \
     'fig06-torso-running-time.csv' skip 2 using 1:4:5 with filledcurves lc rgb '#f28e2b' title 'impulses', \
     'fig06-torso-running-time.csv' skip 2 using 1:3:4 with filledcurves lc rgb '#e15759' title 'collision detection (GJK extrusion, TOI)', \
     'fig06-torso-running-time.csv' skip 2 using 1:2:3 with filledcurves lc rgb '#59a14f' title 'bounding volumes', \
     'fig06-torso-running-time.csv' skip 2 using 1:(0):2 with filledcurves lc rgb '#4e79a7' title 'integration', \
     NaN with lines lc rgb '#ffffff' title 'drawing: none (gjkx_simulate draws no image)', \
     NaN with lines lc rgb '#ffffff' title 'not stacked: the independent checks', \
     NaN with lines lc rgb '#ffffff' title '(not the method): 0% of wall time'
unset multiplot
