# hand_throw_rates.gp — the throw at the target (1999 paper, Experiment 2, Fig. 10; catalog
# scenario hand/throw_at_target) at 12, 17, 30, 60 and 120 frames/s: (a) side view of the block's
# centre G per frame at each rate, with the target (2.0 m +- 0.15 m) on the floor and where each
# rate's block landed; (b) where it came to rest per rate against the target.
# Data: plots/hand_throw_rates.c (run by `make plots` before this script): one CSV, the rates' rows
# one after another, told apart by column 1 (fps). Writes hand_throw_rates.png/.svg.
#   gnuplot -e "traj='build/traj'; out='build/plots'" plots/hand_throw_rates.gp
if (!exists("out")) out = 'build/plots'
set datafile separator ","
set datafile columnheaders
data = out.'/hand_throw_rates.csv'
load out.'/hand_throw_rates.vars'
N = 5
colors = "#9467bd #d62728 #2ca02c #1f77b4 #ff7f0e"
color(i) = word(colors, i)
v(name, i) = value(name.i)
rate(i, col) = column(1) == v("fps", i) ? column(col) : 1/0   # column col of rate i's rows only
hits = 0
misses = ""
do for [i = 1:N] {
    if (v("hit", i)) { hits = hits + 1 } else { misses = misses.(misses eq "" ? "" : ", ").sprintf("1/%d s", v("fps", i)) }
}
verdict = hits == N ? "every rate lands in the target" : sprintf("%d of %d rates land in the target; %s misses", hits, N, misses)

do for [k = 1:2] {
    if (k == 1) {
        set terminal pngcairo size 1300, 1000 enhanced font "Sans,11"
        set output out.'/hand_throw_rates.png'
    } else {
        set terminal svg size 1300, 1000 enhanced font "Sans,11" background rgb "white"
        set output out.'/hand_throw_rates.svg'
    }
    set multiplot title "Throwing a 5 cm block at a target 2 m away (Fig. 10, scenario hand/throw\\_at\\_target) at 12-120 frames/s:\n".verdict font ",13"

    # (a) side view
    set origin 0, 0.36
    set size 1, 0.58
    set title "(a) side view: G every frame per frame time (the same hand script, sampled at each rate); o = release, last held frame"
    set grid
    set xlabel "x [m]"
    set ylabel "z [m]"
    set xrange [-0.25:2.4]
    set yrange [0:1.5]
    set key top right box opaque font ",10"
    set object 1 rect from 1.85, 0 to 2.15, 0.02 fc rgb "#d62728" fs solid 1.0 noborder front
    set label 100 "target:\n|x - 2| < 0.15 m" at 2.17, 0.1 left font ",10" front
    # the landing labels: in the clear space under the arcs, arrows to each landing point
    do for [i = 1:N] {
        lx = v("land_x", i) < 1.2 ? v("land_x", i) - 0.06 : 1.45
        lz = v("land_x", i) < 1.2 ? 0.56 : 0.08 + 0.08 * (N - i)
        set label i sprintf("1/%d s: lands at x = %.3f m (t = %.3f s)", v("fps", i), v("land_x", i), v("land_t", i)) \
            at lx, lz right font ",10" tc rgb color(i) front
        set arrow i from lx + 0.01, lz to v("land_x", i), 0.03 lw 1 lc rgb color(i) front
    }
    plot for [i = 1:N] data using 4:(rate(i, 6)) with linespoints lw 1.2 pt 7 ps 0.35 lc rgb color(i) \
             title sprintf("dt = 1/%d s: released at t = %.3f s from x = %.3f, z = %.3f m", v("fps", i), v("release_t", i), v("release_x", i), v("release_z", i)), \
         for [i = 1:N] '+' using (v("release_x", i)):(v("release_z", i)) every ::0::0 with points pt 6 ps 2 lw 2 lc rgb color(i) notitle
    unset object 1
    unset label
    unset arrow

    # (b) where it rests per rate
    set origin 0, 0
    set size 1, 0.36
    set title "(b) where the block comes to rest per frame rate: distance from the target centre (2, 0); the shaded band is the target"
    set xlabel "frames per second (dt = 1/fps)"
    set ylabel "x at rest [m]"
    set logscale x 2
    set xrange [9:170]
    set xtics ("12" 12, "17" 17, "30" 30, "60" 60, "120" 120)
    set yrange [0.7:2.3]
    set ytics 0.2
    set object 2 rect from 9, 1.85 to 170, 2.15 fc rgb "#ffdddd" fs solid 1.0 noborder behind
    set arrow 20 from 9, 2 to 170, 2 nohead dt 2 lc rgb "#d62728"
    unset key
    do for [i = 1:N] {
        txt = sprintf("x = %.4f m, y = %.4f m:\n%.1f mm from the centre, %s", v("end_x", i), v("end_y", i), 1000 * v("miss", i), v("hit", i) ? "in the target" : "MISSES the target")
        if (v("hit", i)) {
            set label i txt at v("fps", i), v("end_x", i) - 0.22 center font ",9" tc rgb color(i)
        } else {
            set label i txt at v("fps", i) * 1.12, v("end_x", i) + 0.05 left font ",9" tc rgb color(i)
        }
    }
    plot for [i = 1:N] '+' using (v("fps", i)):(v("end_x", i)) every ::0::0 with points pt 7 ps 2 lc rgb color(i) notitle
    unset label
    unset arrow 20
    unset object 2
    unset logscale x
    set xtics autofreq
    set ytics autofreq
    unset multiplot
    set output
}
