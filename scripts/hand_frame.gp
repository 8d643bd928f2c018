# hand_frame.gp — the default right hand's check points in the wrist frame, from `handspring hand`
# (scripts/figures.sh writes out/hand_open.csv and out/hand_grasp.csv first): top and side views.
#   gnuplot -e "out='build/figures'" scripts/hand_frame.gp
if (!exists("out")) out = 'build/figures'
set datafile separator ','
set datafile commentschars '#'
set terminal pngcairo size 1100,520 font ',10'
set output out.'/hand_wrist_frame.png'
set multiplot layout 1,2 title "The default right hand's 20 check points in the wrist frame: open (blue) and grasping 5 cm (orange); the wrist at the origin" font ',11'
set size ratio -1
set grid
set key top left font ',9'
open = out.'/hand_open.csv'
grasp = out.'/hand_grasp.csv'
set title 'top view: x toward the fingertips, y toward the thumb'
set xlabel 'x (m)'
set ylabel 'y (m)'
plot for [f = 0:4] open every ::(4 * f + 1)::(4 * f + 4) using 3:4 with linespoints lw 2 pt 7 lc rgb '#3b6ea5' notitle, \
     for [f = 0:4] grasp every ::(4 * f + 1)::(4 * f + 4) using 3:4 with linespoints lw 2 pt 7 lc rgb '#e07b22' notitle, \
     open every 4::4 using 3:4:2 with labels offset 0, 0.8 font ',8' noenhanced notitle, \
     '+' using (0):(0) every ::0::0 with points pt 6 ps 2 lc rgb 'black' title 'wrist'
set title 'side view: z out of the back of the hand (z stretched: not to the scale of x)'
set size ratio 0.75
set ylabel 'z (m)'
plot for [f = 0:4] open every ::(4 * f + 1)::(4 * f + 4) using 3:5 with linespoints lw 2 pt 7 lc rgb '#3b6ea5' notitle, \
     for [f = 0:4] grasp every ::(4 * f + 1)::(4 * f + 4) using 3:5 with linespoints lw 2 pt 7 lc rgb '#e07b22' notitle, \
     '+' using (0):(0) every ::0::0 with points pt 6 ps 2 lc rgb 'black' title 'wrist'
unset multiplot
