# hand_timeline_noisy.gp — the contact-state timeline of the 1999 paper's Fig. 12 for a grasp
# under realistic input noise (catalog scenario hand/grasp_adjoining_faces): (a) the cube's hand
# contact state (0 no contact, 1 push at one point, 2 grasp, 3 push at several points) against
# time, one strip for the noise-free run and one per noise seed 1..5; (b) the height of the
# cube's centre G in every run, which shows whether the grasp lifts and carries it.
# Data: plots/hand_timeline_noisy.c (run by `make plots` before this script): one CSV, the runs'
# rows one after another, told apart by column 1 (seed, 0 noise-free). Writes
# hand_timeline_noisy.png/.svg.
#   gnuplot -e "traj='build/traj'; out='build/plots'" plots/hand_timeline_noisy.gp
if (!exists("out")) out = 'build/plots'
set datafile separator ","
set datafile columnheaders
data = out.'/hand_timeline_noisy.csv'
load out.'/hand_timeline_noisy.vars'
N = 6
colors = "#000000 #1f77b4 #d62728 #2ca02c #ff7f0e #9467bd"
color(i) = word(colors, i)
v(name, i) = value(name.i)
run_of(i, col) = column(1) == v("seed", i) ? column(col) : 1/0   # column col of run i's rows only
run(i) = i == 1 ? "noise-free" : sprintf("seed %d", v("seed", i))
held = 0
do for [i = 2:N] { held = held + v("holds", i) }
verdict = held == N - 1 ? "every noisy run holds the grasp as long as the noise-free one" : \
          (held == 0 ? sprintf("no noisy run (seeds 1-%d) keeps the grasp: each loses the cube while lifting it", N - 1) : \
           sprintf("%d of %d noisy runs keep the grasp as long as the noise-free one", held, N - 1))
lost(i) = v("holds", i) ? sprintf("holds it; lets go at t = %.3f s", v("lost_t", i)) : \
          sprintf("loses the grasp at t = %.3f s (to state %d)", v("lost_t", i), v("lost_state", i))
nz(x) = abs(x) < 0.0005 ? 0 : x   # no "-0.000"
story(i) = sprintf("%s: %s, grasped at t = %.3f s, %s; G highest %.3f m, rests at (%.3f, %.3f) m", \
                   run(i), v("seq", i), v("grasp_t", i), lost(i), v("max_z", i), nz(v("end_x", i)), nz(v("end_y", i)))
x0 = 0; x1 = 2.5
L = 0.09; R = 0.97

do for [k = 1:2] {
    if (k == 1) {
        set terminal pngcairo size 1300, 1150 enhanced font "Sans,11"
        set output out.'/hand_timeline_noisy.png'
    } else {
        set terminal svg size 1300, 1150 enhanced font "Sans,11" background rgb "white"
        set output out.'/hand_timeline_noisy.svg'
    }
    set multiplot title "Contact states of a noisy grasp (Fig. 12, scenario hand/grasp\\_adjoining\\_faces: thumb on a side face, two fingertips on the top, 90 deg apart)\nwith realistic input noise (glove +-4 units per sensor, wrist 0.762 mm and 0.15 deg), seeds 1-5, against the noise-free run:\n".verdict font ",12"
    set grid
    set xrange [x0:x1]
    set lmargin at screen L
    set rmargin at screen R

    # (a) one strip per run
    top = 0.885
    h = 0.085
    set yrange [-0.4:3.4]
    set ytics ("0" 0, "1" 1, "2" 2, "3" 3) font ",9"
    set xtics 0.1 format ""
    set xlabel ""
    unset key
    do for [i = 1:N] {
        set tmargin at screen top - (i - 1) * h
        set bmargin at screen top - i * h + 0.012
        set ylabel run(i) font ",10"
        set title ""
        if (i == 1) { set title "(a) hand contact state per run (0 no contact, 1 push at one point, 2 grasp, 3 push at several points)" }
        set label 1 story(i) at graph 0.01, graph 0.83 left font ",9" tc rgb color(i) front noenhanced
        plot data using 3:(run_of(i, 4)) with steps lw 2 lc rgb color(i) notitle
        unset label 1
    }

    # (b) the height of G
    set tmargin at screen 0.30
    set bmargin at screen 0.06
    set title "(b) height of the cube's centre G: the script lifts it 0.1 m (t 0.7-1.0 s), carries it 0.2 m along y and puts it down (1.5-1.8 s)"
    set xtics 0.1 format "%.1f" font ",10"
    set xlabel "t [s]"
    set ylabel "G z [m]" font ",11"
    set yrange [0.015:0.14]
    set ytics autofreq font ",10"
    set key top right box opaque font ",9"
    plot for [i = 1:N] data using 3:(run_of(i, 7)) with lines lw (i == 1 ? 3 : 1.8) lc rgb color(i) title run(i)
    unset multiplot
    set output
}
