# spring_tracker.gp — Fig. 6 of the workbench paper ("Tracker positions during lifting and throwing
# manipulations", §5.1), from the catalog scenario spring/recorded_throw: the 50 Hz samples of the
# tracker daemon (a recorded file, resampled to the 60 fps world and sampled again at 50 Hz), the
# ball's path (the scenario's trajectory), and the daemon's speed estimate with its rest / motion
# thresholds, which tell the throw (release while moving) from a drop. The fit rings briefly after
# an abrupt stop (its quadratic overshoots at the kink), which shows as a short return to 'moving'.
# Data: plots/spring_tracker.c and traj/spring/recorded_throw.csv. Writes spring_tracker.png/.svg.
#   gnuplot -e "traj='build/traj'; out='build/plots'" plots/spring_tracker.gp
if (!exists("out")) out = 'build/plots'
if (!exists("traj")) traj = 'build/traj'
set datafile separator ","
set datafile commentschars "#"
data = out.'/spring_tracker.csv'
ball = traj.'/spring/recorded_throw.csv'
# the release: the sample whose `release` column is set (2 = throw)
stats data using ($12 > 0 ? $1 : 1/0) nooutput name "R"
t_release = R_min
# the speed axis holds the whole estimate, its overshoot included
stats data using 9 nooutput name "V"
v_top = V_max > 1.2 ? 1.08 * V_max : 1.3

do for [k = 1:2] {
    if (k == 1) {
        set terminal pngcairo size 1100,900 enhanced font "Sans,11"
        set output out.'/spring_tracker.png'
    } else {
        set terminal svg size 1100,900 enhanced font "Sans,11" background rgb "white"
        set output out.'/spring_tracker.svg'
    }
    set multiplot layout 2,1 title "Tracker positions during lifting and throwing (workbench paper Fig. 6): scenario spring/recorded\\_throw" font ",12"
    set grid
    set lmargin 10
    set rmargin 10
    set xrange [0:3.8]
    set xlabel "time t [s]"
    set style rect fc rgb "#f2f2f2" fs solid 1.0 noborder
    set object 1 rect from 0.7, graph 0 to t_release, graph 1 behind
    set arrow 1 from t_release, graph 0 to t_release, graph 1 nohead dt 2 lw 1.5 lc rgb "#000000"
    set label 1 sprintf("release while moving: throw (t = %.2f s)", t_release) at t_release + 0.03, graph 0.93 font ",10"
    set label 2 "shaded: button pressed" at 0.75, graph 0.93 font ",10"

    set title "(a) stylus as sampled by the tracker daemon at 50 Hz (points) and the ball's centre (lines)"
    set ylabel "position [m]"
    set yrange [-0.7:1.0]
    set key bottom right box opaque
    plot data using 1:2 with points pt 7 ps 0.5 lc rgb "#1f77b4" title "stylus x (tracker samples)", \
         data using 1:4 with points pt 7 ps 0.5 lc rgb "#d62728" title "stylus z (tracker samples)", \
         ball using 2:4 with lines lw 2 lc rgb "#17becf" title "ball x", \
         ball using 2:6 with lines lw 2 lc rgb "#ff7f0e" title "ball z"

    unset label 2
    set title "(b) the daemon's speed estimate (quadratic fit over 9 samples) and its rest / motion detection"
    set ylabel "hand speed [m/s]"
    set yrange [0:v_top]
    set y2label "at rest (1) / moving (0)"
    set y2range [0:v_top]
    set y2tics 0, 1, 1
    set key at graph 0.52, graph 0.98 right top box opaque
    plot data using 1:9 with linespoints pt 7 ps 0.5 lw 1.5 lc rgb "#2ca02c" title "estimated speed |v|", \
         data using 1:10 axes x1y2 with steps lw 1.5 lc rgb "#9467bd" title "at rest", \
         0.2 with lines dt 2 lc rgb "#d62728" title "motion starts above 0.20 m/s", \
         0.1 with lines dt 3 lc rgb "#1f77b4" title "rest resumes below 0.10 m/s"
    unset y2label
    unset y2tics
    unset object 1
    unset arrow 1
    unset label
    unset multiplot
    set output
}
