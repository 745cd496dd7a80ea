# The torso scene in every simulator of the peers table (gjkx_peers_table --frames, docs 08,
# "The peers side by side"), drawn by gnuplot for 08_torso (running_time.hpp, peersFramesFigure):
# per frame, its wall time over its simulated time against simulated time, one line per
# simulator, on a log axis with real time at 1. Fig. 6 shows where our time goes; this shows
# how far each simulator is from real time, frame by frame, on the same scene.
#
# 08_torso runs it in the folder of the data, setting with gnuplot -e:
#   data         the CSV: a frame's start and end time, then each simulator's ratio (a step per frame)
#   out          the figure to write
#   format       its format: png, svg or pdf (08_torso's --format)
#   count        the number of simulators; name1, name2, ... their names, in the data's column order
#   xmax         the simulated time at the runs' end
#   bottom, top  the log axis's range
colours = "#e15759 #4e79a7 #b07aa1 #f28e2b #59a14f #76b7b2"  # ours first, then the peers

# 1200 pixels wide, or 12.5 inches (pdfcairo's unit) at 96 pixels an inch.
if (format eq 'svg') {
  set terminal svg size 1200,560 font 'sans,11'
} else {
  if (format eq 'pdf') {
    set terminal pdfcairo size 12.5,5.83 font 'sans,11'
  } else {
    set terminal pngcairo size 1200,560 font 'sans,11'
  }
}
set output out
set datafile separator ','
set title "Each frame's wall time over its simulated time: the torso scene in every simulator of the peers table\n(gjkx_peers_table --frames; one run each, on one core; 1 is real time)" noenhanced
set key inside center bottom opaque box noenhanced
set logscale y
set yrange [bottom:top]
set format y '%g'
set xrange [0:xmax]
set xlabel 'simulated time (s)'
set ylabel 'frame wall time / frame simulated time'
set grid ytics
plot 1 with lines lc rgb 'black' lw 1.5 title 'real time', \
     for [i=1:count] data using 1:(column(i + 1)) with lines lw 2 lc rgb word(colours, i) title value(sprintf('name%d', i))
