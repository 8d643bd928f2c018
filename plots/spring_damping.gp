# spring_damping.gp — Fig. 2 of the workbench paper ("Damping examples", §4.3): the spring-damper
# released from x(0) = 0.2 x0 at rest, under-, critically and over-damped, closed forms against
# simulation points; and the library's four integrators at a coarse dt = 1/12 s on the critical case.
# Data: plots/spring_damping.c (run by `make plots` before this script). Writes spring_damping.png/.svg.
#   gnuplot -e "traj='build/traj'; out='build/plots'" plots/spring_damping.gp
if (!exists("out")) out = 'build/plots'
set datafile separator ","
set datafile commentschars "#"
curves = out.'/spring_damping_curves.csv'
points = out.'/spring_damping_points.csv'
integ = out.'/spring_damping_integrators.csv'

do for [k = 1:2] {
    if (k == 1) {
        set terminal pngcairo size 1100,900 enhanced font "Sans,11"
        set output out.'/spring_damping.png'
    } else {
        set terminal svg size 1100,900 enhanced font "Sans,11" background rgb "white"
        set output out.'/spring_damping.svg'
    }
    set multiplot layout 2,1 title "Spring-damper m x'' + c x' + k x = 0 from x(0) = 0.2 x_0 at rest: 1000 kg, x_0 = 1 m, ω = 7.00 rad/s (workbench paper Fig. 2)" font ",12"
    set grid
    set xrange [0:2.5]
    set xlabel "time t [s]"
    set ylabel "displacement from rest x(t) / x(0)"
    set key top right box opaque
    set title "(a) damping ratio ζ = c / 2√(km): closed forms (lines) and simulations at dt = 1/30 s (points)"
    plot curves using 1:2 with lines lw 2 lc rgb "#1f77b4" title "under-damped ζ = 0.25 (closed form)", \
         curves using 1:3 with lines lw 2 lc rgb "#d62728" title "critically damped ζ = 1 (closed form)", \
         curves using 1:4 with lines lw 2 lc rgb "#2ca02c" title "over-damped ζ = 2 (closed form)", \
         points using 1:3 with points pt 6 ps 1.0 lc rgb "#1f77b4" title "ζ = 0.25: RK4 of the same equation (generator)", \
         points using 1:2 with points pt 7 ps 1.0 lc rgb "#d62728" title "ζ = 1: handspring (exact integrator)", \
         points using 1:4 with points pt 4 ps 1.0 lc rgb "#2ca02c" title "ζ = 2: RK4 of the same equation (generator)", \
         0 with lines lc rgb "black" lw 1 notitle
    set xrange [0:1.5]
    set title "(b) the critically damped case stepped by handspring at dt = 1/12 s (ω dt = 0.58), one point per frame"
    plot curves using 1:3 with lines lw 2 lc rgb "#d62728" title "closed form e^{-ωt}(1 + ωt)", \
         integ using 1:2 with linespoints pt 7 ps 1.1 lw 1 dt 2 lc rgb "#000000" title "exact (closed-form step)", \
         integ using 1:3 with linespoints pt 5 ps 0.9 lw 1 dt 2 lc rgb "#9467bd" title "implicit Euler", \
         integ using 1:4 with linespoints pt 9 ps 1.1 lw 1 dt 2 lc rgb "#ff7f0e" title "semi-implicit Euler", \
         integ using 1:5 with linespoints pt 13 ps 1.0 lw 1 dt 2 lc rgb "#17becf" title "RK4", \
         0 with lines lc rgb "black" lw 1 notitle
    unset multiplot
    set output
}
