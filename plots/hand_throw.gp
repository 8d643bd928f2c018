# hand_throw.gp — the throw at the target (1999 paper, Experiment 2, Fig. 10; catalog scenario
# hand/throw_at_target): (a) side view of the block's centre G per frame, held and flying, with
# the hand's path, the closed-form parabola of eq. 3 and the target on the floor; (b) top view of
# the target (radius 0.15 m, 2 m away) with where the block came to rest.
# Data: plots/hand_throw.c (run by `make plots` before this script). Writes hand_throw.png/.svg.
#   gnuplot -e "traj='build/traj'; out='build/plots'" plots/hand_throw.gp
if (!exists("out")) out = 'build/plots'
set datafile separator ","
set datafile commentschars "#"
set datafile columnheaders
data = out.'/hand_throw.csv'

# release (scenario comments, docs/model.md §4 "Release"): G at R = (0.147, 0.55) after frame 78,
# the hand moving at v = (2.47, 3.0) m/s; let go in frame 79, taken as mid-frame, the block's
# frames lie on P(tau) = R + v tau - g (tau^2 - tau dt) / 2, tau = n dt after frame 78
dt = 1.0 / 60
g = 9.81
rx = 0.147; rz = 0.55; vx = 2.47; vz = 3.0
fx(tau) = rx + vx * tau
fz(tau) = rz + (vz + g * dt / 2) * tau - g * tau**2 / 2
tau_land = ((vz + g * dt / 2) + sqrt((vz + g * dt / 2)**2 + 2 * g * (rz - 0.025))) / g

# where it rests: the last row
stats data using 1 nooutput
last = STATS_records - 1
stats data every ::last::last using 3 nooutput
x_end = STATS_max
stats data every ::last::last using 4 nooutput
y_end = STATS_max
miss = sqrt((x_end - 2)**2 + y_end**2)

do for [k = 1:2] {
    if (k == 1) {
        set terminal pngcairo size 1200,900 enhanced font "Sans,11"
        set output out.'/hand_throw.png'
    } else {
        set terminal svg size 1200,900 enhanced font "Sans,11" background rgb "white"
        set output out.'/hand_throw.svg'
    }
    set multiplot title "Throwing a 5 cm block at a target 2 m away (1999 paper, Experiment 2, Fig. 10): scenario hand/throw\\_at\\_target" font ",13"

    # (a) side view
    set origin 0, 0.38
    set size 1, 0.58
    set title "(a) side view: the block's centre G every frame (1/60 s), the hand, and the parabola it flies on"
    set grid
    set xlabel "x [m]"
    set ylabel "z [m]"
    set xrange [-0.25:2.35]
    set yrange [0:1.45]
    set key top right box opaque
    set parametric
    set trange [0:tau_land]
    set samples 400
    set style rect fc rgb "#ffdddd" fs solid 1.0 noborder
    set object 1 rect from 1.85, 0 to 2.15, 0.02 fc rgb "#d62728" front
    set label 1 "target: |x - 2| < 0.15 m" at 1.55, 0.07 font ",10" front
    set label 2 "release, t = 1.3 s:\nv = (2.47, 0, 3.0) m/s" at 0.2, 0.5 font ",10"
    set arrow 1 from 0.19, 0.52 to 0.152, 0.548 lw 1 lc rgb "#333333"
    set label 3 sprintf("rests at x = %.4f m,\n%.1f mm from the centre", x_end, 1000 * miss) at 1.36, 0.23 font ",10"
    set arrow 2 from 1.72, 0.17 to x_end - 0.01, 0.04 lw 1 lc rgb "#333333"
    set label 4 "pick-up" at -0.2, 0.12 font ",10"
    set label 5 "wind-up" at -0.245, 0.33 font ",10"
    plot data using 7:9 with lines lw 1.5 dt 2 lc rgb "#7f7f7f" title "hand (mean of its 20 check points)", \
         data using ($6 == 2 ? $3 : 1/0):5 with points pt 7 ps 0.6 lc rgb "#1f77b4" title "G, grasped (state 2)", \
         data using ($6 == 0 && $1 > 60 ? $3 : 1/0):5 with points pt 7 ps 0.6 lc rgb "#ff7f0e" title "G, free (state 0): eq. 3", \
         fx(t), fz(t) with lines lw 1 lc rgb "#000000" title sprintf("closed form from the release, meeting the floor at t = %.3f s", 1.3 + tau_land)
    unset parametric
    unset object 1
    unset label
    unset arrow

    # (b) top view of the target
    set origin 0.2, 0.0
    set size 0.6, 0.38
    set title "(b) top view: the target (radius 0.15 m) and the block at rest"
    set xlabel "x [m]"
    set ylabel "y [m]"
    set size ratio -1
    set xrange [1.75:2.25]
    set yrange [-0.2:0.2]
    set key outside right box
    set object 2 circle at 2, 0 size 0.15 fc rgb "#ffdddd" fs solid 1.0 border lc rgb "#d62728" behind
    set object 3 rect from x_end - 0.025, y_end - 0.025 to x_end + 0.025, y_end + 0.025 fc rgb "#ffbb78" fs solid 1.0 border lc rgb "#000000" behind
    set parametric
    set trange [0:2*pi]
    plot 2 + 0.15 * cos(t), 0.15 * sin(t) with lines lw 2 lc rgb "#d62728" title "target, r = 0.15 m", \
         x_end, y_end with points pt 1 ps 2 lc rgb "#000000" title "G at rest (block outline 5 cm)", \
         2, 0 with points pt 2 ps 1.5 lc rgb "#d62728" title "target centre (2, 0)"
    unset parametric
    unset object 2
    unset object 3
    set size noratio
    unset multiplot
    set output
}
