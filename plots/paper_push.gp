# paper_push.gp — the 1999 paper's Fig. 3 (pushing an object at one point) from the model's own
# numbers: plots/paper_push.c's CSVs (hand/push_off_centre). (a) the box seen from above at the
# start, after the first push frame and at the end, and the fingertip's path; (b) that frame at C:
# CB split into T (along CG) and R (normal to it) by eq. 1, drawn 10 times longer.
#   gnuplot -e "out='build/plots'" plots/paper_push.gp    (after paper_push OUT)
if (!exists("out")) out = 'build/plots'
set datafile separator ","
set datafile columnheaders
f = out.'/paper_push.csv'
o = out.'/paper_push_outline.csv'
stats f using 1 nooutput
frame = int(STATS_max)
stats f using 17 nooutput
theta = STATS_max
stats f using 24 nooutput
turned = STATS_max
k = 10.0   # the frame's vectors are millimetres: drawn k times longer
set terminal pngcairo size 1200, 680 enhanced font "Sans,11"
set output out.'/paper_push.png'
set multiplot layout 1, 2 title sprintf("1999 paper Fig. 3 from hand/push\\_off\\_centre: a fingertip pushes a box at one point (eq. 1-2)") font ",13"
set size ratio -1
set grid
set key bottom right opaque box font ",10"
set xlabel "x [m]"
set ylabel "y [m]"
set title "(a) seen from above: start, after the first push frame, end"
set xrange [-0.16:0.16]
set yrange [-0.16:0.16]
set key below
plot o using (strcol(1) eq 'start' ? $2 : 1/0):3:4:5 with vectors nohead lw 2 lc rgb "#9a9a9a" title "start", \
     o using (strcol(1) eq 'pushed' ? $2 : 1/0):3:4:5 with vectors nohead lw 2 lc rgb "#1f77b4" title sprintf("frame %d: pushed at one point", frame), \
     o using (strcol(1) eq 'end' ? $2 : 1/0):3:4:5 with vectors nohead lw 2 dt 2 lc rgb "#e07b22" title "end (turned, slid)", \
     o using (strcol(1) eq 'tip' ? $2 : 1/0):3:4:5 with vectors nohead lw 3 lc rgb "#d62728" title "index fingertip's path", \
     f using 8:9 with points pt 7 ps 1.5 lc rgb "black" title "G"
set title sprintf("(b) frame %d at C: CB = T + R, T along CG (vectors x %g)\nθ = atan(|R| / |CG|) = %.4f°; the model turned\nthe box %.4f° and moved G by T", frame, k, theta, turned)
set xrange [-0.06:0.01]
set yrange [0.005:0.07]
set key below
plot o using (strcol(1) eq 'start' ? $2 : 1/0):3:4:5 with vectors nohead lw 1 lc rgb "#9a9a9a" notitle, \
     f using 2:3:($8 - $2):($9 - $3) with vectors nohead dt 3 lw 1.5 lc rgb "black" title "C to G", \
     f using 2:3:(k * ($5 - $2)):(k * ($6 - $3)) with vectors lw 3 lc rgb "black" title "CB (C to B)", \
     f using 2:3:(k * $11):(k * $12) with vectors lw 3 lc rgb "#1f77b4" title "T: translation, along CG", \
     f using ($2 + k * $11):($3 + k * $12):(k * $14):(k * $15) with vectors lw 3 lc rgb "#d62728" title "R: turns the box about X = R x CG (through G)", \
     f using 2:3 with points pt 7 ps 1.5 lc rgb "#2ca02c" title "C: contact point", \
     f using 2:3:("C") with labels offset -1.5, 0 notitle, \
     f using ($2 + k * ($5 - $2)):($3 + k * ($6 - $3)):("B") with labels offset 1, 0.6 notitle
unset multiplot
set output
