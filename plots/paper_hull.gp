# paper_hull.gp — the 1999 paper's Figs. 5 and 6 (an object on the floor, §4.2) from the model's own
# state: plots/paper_hull.c's CSVs, six catalog scenarios each at one frame, seen from above: the
# floor vertices V_i, their convex hull, G, G' (G projected onto the floor along Gm; the dashed line
# from G to G' is Gm extended to the floor, seen from above), rule (2)'s perpendiculars through
# V1 and V2, the vertex or line the model turns about next, and the object at that frame and the next.
#   gnuplot -e "out='build/plots'" plots/paper_hull.gp    (after paper_hull OUT)
if (!exists("out")) out = 'build/plots'
load out.'/paper_hull.vars'
set datafile separator ","
set datafile columnheaders
f = out.'/paper_hull.csv'
s = out.'/paper_hull_shapes.csv'
set terminal pngcairo size 1560, 1160 noenhanced font "Sans,10"
set output out.'/paper_hull.png'
set multiplot title "1999 paper Figs. 5-6 from the model's state: the floor vertices V_i, their convex hull, G and G' (G projected onto the floor along Gm, eq. 5),\nand what the model turns about next; seen from above, x and y in m. θ: eq. 7's turn. Each panel's last line: what the model did the next frame (checked by plots/paper_hull.c)" font ",12"
set size ratio -1
set grid lc rgb "#e8e8e8"
set xtics 0.05
set ytics 0.05
unset key
kind(k) = strcol(2) eq k
do for [i = 1:6] { # three panels a row, two rows, over the legend's strip
	set origin (i - 1) % 3 / 3.0, 0.07 + (i <= 3 ? 0.43 : 0.0)
	set size 1 / 3.0, 0.43
	set title value(sprintf("title%d", i)) font ",10"
	set xrange [value(sprintf("xmin%d", i)):value(sprintf("xmax%d", i))]
	set yrange [value(sprintf("ymin%d", i)):value(sprintf("ymax%d", i))]
	plot s using (column(1) == i && kind('outline') ? $4 : 1/0):5:6:7 with vectors nohead lw 1 lc rgb "#9a9a9a", \
	     s using (column(1) == i && kind('next') ? $4 : 1/0):5:6:7 with vectors nohead lw 1 dt 2 lc rgb "#e8a35c", \
	     s using (column(1) == i && kind('perp') ? $4 : 1/0):5:6:7 with vectors nohead lw 1.2 dt 3 lc rgb "#555555", \
	     s using (column(1) == i && kind('pivot') && column(3) == 2 ? $4 : 1/0):5:6:7 with vectors nohead lw 9 lc rgb "#f5b041", \
	     s using (column(1) == i && kind('pivot') && column(3) == 1 ? $4 : 1/0):5 with points pt 7 ps 4 lc rgb "#f5b041", \
	     s using (column(1) == i && kind('hull') ? $4 : 1/0):5:6:7 with vectors nohead lw 2.5 lc rgb "#1f5fa8", \
	     s using (column(1) == i && kind('vertex') ? $4 : 1/0):5 with points pt 7 ps 1.2 lc rgb "#1f5fa8", \
	     s using (column(1) == i && kind('vertex') ? $4 : 1/0):5:(sprintf("V%d", int(column(3)))) with labels offset 1.4, -0.9 tc rgb "#1f5fa8", \
	     f using (column(1) == i ? $7 : 1/0):8:($13 - $7):($14 - $8) with vectors nohead lw 1.5 dt 2 lc rgb "black", \
	     f using (column(1) == i ? $7 : 1/0):8 with points pt 6 ps 2 lc rgb "black", \
	     f using (column(1) == i ? $7 : 1/0):8:("G") with labels offset -1.3, 1 tc rgb "black", \
	     f using (column(1) == i ? $13 : 1/0):14:(column(15) != 0 ? 0x2ca02c : 0xd62728) with points pt 3 ps 2.6 lw 2.5 lc rgb variable, \
	     f using (column(1) == i ? $13 : 1/0):14:("G'") with labels offset 1.6, 1 font ",11"
}
# the legend, once, under the panels
set origin 0, 0
set size 1, 0.07
unset title
unset border
unset tics
unset grid
set xrange [0:1]
set yrange [0:1]
set key horizontal center center samplen 2.5 font ",10"
plot '+' using (NaN):(NaN) with lines lw 1 lc rgb "#9a9a9a" title "the object at the frame", \
     '+' using (NaN):(NaN) with lines lw 1 dt 2 lc rgb "#e8a35c" title "at the next frame", \
     '+' using (NaN):(NaN) with points pt 7 lc rgb "#1f5fa8" title "floor vertices V_i", \
     '+' using (NaN):(NaN) with lines lw 2.5 lc rgb "#1f5fa8" title "their convex hull", \
     '+' using (NaN):(NaN) with points pt 6 ps 2 lc rgb "black" title "G (above the floor)", \
     '+' using (NaN):(NaN) with lines lw 1.5 dt 2 lc rgb "black" title "G to G' along Gm", \
     '+' using (NaN):(NaN) with points pt 3 ps 2 lw 2.5 lc rgb "#2ca02c" title "G' inside", \
     '+' using (NaN):(NaN) with points pt 3 ps 2 lw 2.5 lc rgb "#d62728" title "G' outside", \
     '+' using (NaN):(NaN) with lines lw 1.2 dt 3 lc rgb "#555555" title "perpendiculars through V1, V2", \
     '+' using (NaN):(NaN) with lines lw 9 lc rgb "#f5b041" title "turns about (vertex or line)"
unset multiplot
set output
