# spring_lift.gp — lift, swing and drop (workbench paper Fig. 7–8, catalog scenario
# spring/lift_swing_drop): heights of the stylus and the object, the spring's extension, and the
# swing (horizontal offset of G from the stylus) against the critically damped closed form.
# Data: plots/spring_lift.c (run by `make plots` before this script). Writes spring_lift.png/.svg.
#   gnuplot -e "traj='build/traj'; out='build/plots'" plots/spring_lift.gp
if (!exists("out")) out = 'build/plots'
set datafile separator ","
set datafile commentschars "#"
data = out.'/spring_lift.csv'
# closed form of the swing: a hand speed jump dw gives dw t exp(-w_p t), w_p = sqrt(g / 1.2 x0)
wp = sqrt(9.81 / 0.12)
dw = sqrt(0.4**2 + 0.2**2)
swing(t) = t < 3.0 ? 1/0 : t < 4.0 ? dw * (t - 3.0) * exp(-wp * (t - 3.0)) : t < 5.5 ? dw * (t - 4.0) * exp(-wp * (t - 4.0)) : 1/0

do for [k = 1:2] {
    if (k == 1) {
        set terminal pngcairo size 1100,1100 enhanced font "Sans,11"
        set output out.'/spring_lift.png'
    } else {
        set terminal svg size 1100,1100 enhanced font "Sans,11" background rgb "white"
        set output out.'/spring_lift.svg'
    }
    set multiplot layout 3,1 title "Lift, swing and drop of a 1 kg cube (x_0 = 0.1 m, k = 490.5 N/m): scenario spring/lift\\_swing\\_drop" font ",12"
    set grid
    set xrange [0:6.5]
    set xlabel "time t [s]"
    set style rect fc rgb "#f2f2f2" fs solid 1.0 noborder
    set object 1 rect from 0.8, graph 0 to 5.5, graph 1 behind
    set label 1 "shaded: button pressed, spring attached" at 0.85, graph 0.06 font ",10"
    set title "(a) heights"
    set ylabel "z [m]"
    set yrange [0:0.5]
    set label 2 "into the cube" at 0.05, 0.47 font ",10"
    set label 3 "lift" at 1.3, 0.47 font ",10"
    set label 4 "hold" at 2.35, 0.47 font ",10"
    set label 5 "carry" at 3.3, 0.47 font ",10"
    set label 6 "hold" at 4.6, 0.47 font ",10"
    set label 7 "drop" at 5.55, 0.47 font ",10"
    set key at 5.4, 0.29 right box opaque
    plot data using 1:4 with lines lw 2 lc rgb "#1f77b4" title "stylus", \
         data using 1:7 with lines lw 2 lc rgb "#d62728" title "object centre G", \
         0.33 with lines dt 2 lc rgb "#555555" title "hanging at rest: 0.45 - 1.2 x_0 = 0.33 m", \
         0.05 with lines dt 3 lc rgb "#8c564b" title "G on the floor (half the cube)"
    unset label 2
    unset label 3
    unset label 4
    unset label 5
    unset label 6
    unset label 7

    set title "(b) spring extension (extension / rest length x_0; compressed below 0)"
    set ylabel "extension / x_0"
    set yrange [-1.1:0.6]
    set key bottom right box opaque
    plot data using 1:12 with lines lw 2 lc rgb "#2ca02c" title "extension / x_0 (hs\\_world\\_spring\\_state)", \
         0.2 with lines dt 2 lc rgb "#555555" title "0.2: weight m g held by k = m g / 0.2 x_0 (§4.2)"

    set title "(c) swing: horizontal distance of G from the stylus, against the critically damped closed form"
    set ylabel "offset [m]"
    set logscale y
    set yrange [1e-7:1]
    set format y "10^{%L}"
    set key top right box opaque
    set samples 2000
    plot data using 1:($13 > 0 ? $13 : 1/0) with lines lw 2 lc rgb "#9467bd" title "simulation", \
         swing(x) with lines dt 2 lw 2 lc rgb "#000000" title "closed form Δw t e^{-ω_p t}, Δw = 0.447 m/s, ω_p = 9.04 rad/s"
    unset logscale y
    set format y
    unset object 1
    unset multiplot
    set output
}
