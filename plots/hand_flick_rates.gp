# hand_flick_rates.gp — the flick (1999 paper, Experiment 1 (3), Fig. 9; catalog scenario
# hand/flick_pyramid) at 12, 17, 30, 60 and 120 frames/s: (a) the angle the pyramid has turned
# since frame 0 against time per rate, with where it comes to rest (its face on the floor and the
# angle); (b) its hand contact state per rate (0 none, 1 push at one point).
# Data: plots/hand_flick_rates.c (run by `make plots` before this script): one CSV, the rates' rows
# one after another, told apart by column 1 (fps). Writes hand_flick_rates.png/.svg.
#   gnuplot -e "traj='build/traj'; out='build/plots'" plots/hand_flick_rates.gp
if (!exists("out")) out = 'build/plots'
set datafile separator ","
set datafile columnheaders
data = out.'/hand_flick_rates.csv'
load out.'/hand_flick_rates.vars'
N = 5
colors = "#9467bd #d62728 #2ca02c #1f77b4 #ff7f0e"
color(i) = word(colors, i)
v(name, i) = value(name.i)
rate(i, col) = column(1) == v("fps", i) ? column(col) : 1/0   # column col of rate i's rows only
face(i) = v("end_floor", i) == 3 ? "a side face (3 vertices)" : (v("end_floor", i) == 4 ? "its base (4 vertices)" : sprintf("%d vertices", v("end_floor", i)))
over = 0
tipped = ""
do for [i = 1:N] {
    if (v("end_floor", i) == 3) { over = over + 1; tipped = tipped.(tipped eq "" ? "" : ", ").sprintf("1/%d s", v("fps", i)) }
}
verdict = over == N ? "it tips over onto a side face at every rate" : \
          (over == 0 ? "it only rocks and falls back onto its base at every rate" : \
           sprintf("it tips over onto a side face only at %s; at the other rates it rocks and falls back onto its base", tipped))
t_end = 2.6 # the scenario's duration
# the window: from 0.1 s before the earliest push, 0.5 s wide (the stroke and the fall that follows)
t0 = 1e9
do for [i = 1:N] { if (v("push_t", i) < t0) { t0 = v("push_t", i) } }
t0 = floor((t0 - 0.1) * 20) / 20.0
t1 = t0 + 0.5

do for [k = 1:2] {
    if (k == 1) {
        set terminal pngcairo size 1300, 1000 enhanced font "Sans,11"
        set output out.'/hand_flick_rates.png'
    } else {
        set terminal svg size 1300, 1000 enhanced font "Sans,11" background rgb "white"
        set output out.'/hand_flick_rates.svg'
    }
    set multiplot title "Flicking an 8 cm pyramid with the index fingertip (Fig. 9, scenario hand/flick\\_pyramid) at 12-120 frames/s:\n".verdict font ",13"
    set grid
    set xrange [t0:t1]
    set xtics 0.05

    # (a) the angle turned
    set origin 0, 0.34
    set size 1, 0.6
    set title sprintf("(a) the angle the pyramid has turned since frame 0 (the same stroke sampled at each rate); the end poses are those at t = %.1f s", t_end)
    set xlabel "t [s]"
    set ylabel "turned since frame 0 [deg]"
    set yrange [-5:135]
    set ytics 15
    set key top left box opaque font ",10"
    set arrow 1 from t0, 116.565 to t1, 116.565 nohead dt 3 lc rgb "#555555"
    set label 1 "180 - atan(2h/b) = 116.57 deg: lying on a side face" at t1 - 0.005, 121 right font ",10"
    # each rate's outcome, in the empty space right of the stroke
    do for [i = 1:N] {
        set label 10 + i sprintf("1/%d s: pushed from t = %.3f s, turns at most %.1f deg;\n    rests on %s, turned %.2f deg, G at x = %.4f, z = %.4f m", \
                                 v("fps", i), v("push_t", i), v("max_turn", i), face(i), v("end_turn", i), v("end_x", i), v("end_z", i)) \
            at t0 + 0.262, 58 - 12.5 * (i - 1) left font ",9" tc rgb color(i) front
    }
    plot for [i = 1:N] data using 3:(rate(i, 7)) with linespoints lw 2 pt 7 ps 0.6 lc rgb color(i) title sprintf("dt = 1/%d s", v("fps", i))
    unset label
    unset arrow 1

    # (b) the contact state
    set origin 0, 0
    set size 1, 0.34
    set title "(b) hand contact state per rate (0 no contact, 1 push at one point; lines offset by 0.05 each so that all show)"
    set ylabel "state"
    set yrange [-0.2:1.5]
    set ytics ("0" 0, "1" 1)
    unset key
    plot for [i = 1:N] data using 3:(rate(i, 6) + 0.05 * (i - 1)) with steps lw 2 lc rgb color(i) notitle, \
         for [i = 1:N] '+' using (t0 + 0.32 + 0.035 * (i - 1)):(1.3) every ::0::0 with points pt 7 ps 1.2 lc rgb color(i) notitle, \
         for [i = 1:N] '+' using (t0 + 0.327 + 0.035 * (i - 1)):(1.3):(sprintf("1/%d s", v("fps", i))) every ::0::0 with labels left font ",10" tc rgb color(i) notitle
    unset multiplot
    set output
}
