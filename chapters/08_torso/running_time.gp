# Fig. 6 of the paper, "Running Time for Torso-Plant Simulation", drawn by gnuplot for
# 08_torso (chapter 08, running_time.hpp runningTimeFigure), and its companion of the run under the
# hybrid contact model on the same axes: per frame, the method's execution time
# over the frame's simulated time, stacked by part, against simulated time; the real-time
# line y = 1 and the paper's range for comparison. When the frames and the paper's range
# span more than a factor 30 (twoPanels = 1), a stack on a log axis would misstate the
# parts' shares, so the figure has two panels on one time axis: above, the total on a log
# axis against real time and the paper; below, the stack by part on a linear axis.
#
# 08_torso runs it in the folder of the data, setting with gnuplot -e:
#   data         the CSV of the stacked values: time, then the top of each part (two header lines)
#   out          the figure to write
#   format       its format: png, svg or pdf (08_torso's --format)
#   description  how the run was made (the title's second line)
#   parts        the number of parts; part1, part2, ... their names, bottom to top
#   checksNote   the share of wall time the independent checks (not the method) took
#   band         the key of the paper's range ratioMin to ratioMax
#   ratioMin, ratioMax   the paper's range of execution over simulated time
#   xmax         the simulated time at the run's end
#   twoPanels    1 or 0, as above; with two panels: bottom and top, the log axis's range, and
#   stackTop     the linear axis's top; with one panel: stackTop, its axis's top
colours = "#4e79a7 #59a14f #e15759 #f28e2b #b07aa1 #76b7b2"  # the parts' colours, bottom to top (the last: the hybrid's contact solver)
total = parts + 1  # the column of the top of the stack

# 1200 pixels wide, or 12.5 inches (pdfcairo's unit) at 96 pixels an inch.
if (format eq 'svg') {
  set terminal svg size 1200,(twoPanels ? 860 : 620) font 'sans,11'
} else {
  if (format eq 'pdf') {
    set terminal pdfcairo size 12.5,(twoPanels ? 8.96 : 6.46) font 'sans,11'
  } else {
    set terminal pngcairo size 1200,(twoPanels ? 860 : 620) font 'sans,11'
  }
}
set output out
set datafile separator ','
set termoption noenhanced
set xrange [0:xmax]
set grid ytics lc rgb '#dddddd'
set lmargin at screen 0.08
set rmargin at screen 0.64
set key at screen 0.655, graph 1 left top Left reverse samplen 2 spacing 1.2
set style fill solid 0.9 noborder
set multiplot title "Fig. 6: running time of the torso-plant simulation\n".description font ',12'

# The paper's range and real time (with our total above, or with the stack on one panel).
paperAndRealTime = "ratioMin with filledcurves y=ratioMax fs transparent solid 0.25 lc rgb '#999999' title band, \
     ratioMax with lines dt 2 lw 1.5 lc rgb '#777777' notitle, \
     ratioMin with lines lw 2 lc rgb '#000000' title 'real time (execution = simulation)'"
# The stack by part, top first (so that each part's band is drawn over the one below), and
# in the key what is not stacked: drawing (none) and the independent checks.
stack = "for [p=parts:1:-1] data skip 2 using 1:(p == 1 ? 0 : column(p)):(column(p + 1)) \
       with filledcurves lc rgb word(colours, p) title value('part'.p), \
     NaN with lines lc rgb '#ffffff' title 'drawing: none (gjkx_simulate draws no image)', \
     NaN with lines lc rgb '#ffffff' title 'not stacked: the independent checks', \
     NaN with lines lc rgb '#ffffff' title checksNote"

if (twoPanels) {
  set tmargin at screen 0.89
  set bmargin at screen 0.56
  set logscale y
  set format y '%g'
  set yrange [bottom:top]
  set format x ''
  set ylabel 'execution / simulation time' offset 1,0
  plot @paperAndRealTime, \
       data skip 2 using 1:(column(total) > bottom ? column(total) : bottom) with lines lw 2 lc rgb word(colours, 3) \
       title 'ours: every part (the top of the stack below)'
  unset logscale y
  set format x '%g'
  set tmargin at screen 0.50
  set bmargin at screen 0.08
  set yrange [0:stackTop]
  set format y '%g'
  set ylabel 'execution / simulation time (linear: the parts)' offset -1,0
  set xlabel 'simulated time (s)'
  plot @stack
} else {
  set tmargin at screen 0.87
  set bmargin at screen 0.11
  set yrange [0:stackTop]
  set ylabel 'execution time / simulation time'
  set xlabel 'simulated time (s)'
  plot @stack, @paperAndRealTime
}
unset multiplot
