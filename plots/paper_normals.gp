# paper_normals.gp — the 1999 paper's Fig. 4 (the pseudo-normal of an edge, the grasp check) from
# the model's own contacts: plots/paper_normals.c's CSVs (hand/two_hands_pass, the first frame a
# hand touches the block at three or more parts, one a check line across an edge), seen along y:
# each contact C with its normal N (a face's, or the edge's pseudo-normal, from G to the edge).
#   gnuplot -e "out='build/plots'" plots/paper_normals.gp    (after paper_normals OUT)
if (!exists("out")) out = 'build/plots'
load out.'/paper_normals.vars'
set datafile separator ","
set datafile columnheaders
f = out.'/paper_normals.csv'
e = out.'/paper_normals_edges.csv'
L = 0.03   # drawn length of a normal, m
set terminal pngcairo size 900, 720 enhanced font "Sans,11"
set output out.'/paper_normals.png'
set title sprintf("1999 paper Fig. 4 from hand/two\\_hands\\_pass, frame %d: the normal N_i at each contact C_i\n(an edge's: its pseudo-normal, from G to the edge); the widest pair %.0f° ≥ 90°: grasped (state %d)\n%s", frame, widest, state, pairs) font ",11"
set size ratio -1
set grid
set key below
set xlabel "x [m]"
set ylabel "z [m]"
set xrange [-0.07:0.07]
set yrange [-0.01:0.09]
plot e using 1:3:4:6 with vectors nohead lw 2 lc rgb "#3b6ea5" title "the block's edges (seen along y)", \
     f using (column(3) != 0 ? $10 : 1/0):12:(gx - $10):(gz - $12) with vectors nohead dt 2 lw 1.5 lc rgb "black" title "G to the edge: the pseudo-normal's line", \
     f using 4:6:(L * $7):(L * $9) with vectors lw 3 lc rgb "#d62728" title "N_i at each contact C_i", \
     f using 4:6 with points pt 7 ps 1.3 lc rgb "#2ca02c" title "C_i", \
     f using ($4 + 1.15 * L * $7):($6 + 1.15 * L * $9):(sprintf("N%d%s", int(column(1)), column(3) != 0 ? " (edge)" : "")) with labels notitle, \
     '+' using (gx):(gz) every ::0::0 with points pt 6 ps 2 lc rgb "black" title "G"
set output
