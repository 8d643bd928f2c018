# hand_timeline.gp — the contact-state timeline of the 1999 paper's Fig. 12: each object's hand
# contact state (0 no contact, 1 push at one point, 2 grasp, 3 push at several points) against the
# frame, one line per object, from a catalog trajectory (build/traj/<name>.csv, columns
# frame,t,object,x,y,z,qw,qx,qy,qz,contact,floor,resting,hash). A second panel shows each object's
# height, and for a single object the angle it has turned since frame 0.
#
#   gnuplot -e "traj='build/traj'; out='build/plots'" plots/hand_timeline.gp
#       a grasp's approach (hand/push_then_grasp: states 0, 1, 3, 2, 0 as in Fig. 12): hand_timeline.png/.svg,
#       and every hand/ scenario's
#       states side by side: hand_timeline_catalog.png/.svg
#   gnuplot -e "traj='build/traj'; out='build/plots'; scn='hand/two_hands_pass'" plots/hand_timeline.gp
#       any catalog scenario: hand_timeline_two_hands_pass.png/.svg
if (!exists("traj")) traj = 'build/traj'
if (!exists("out")) out = 'build/plots'
set datafile separator ","
set datafile commentschars "#"
set datafile columnheaders

# the objects of a trajectory, in file order, and each one's state sequence with repeats collapsed
objects(f) = system("grep -v '^#' '".f."' | tail -n +2 | cut -d, -f3 | awk '!seen[$0]++' | tr '\\n' ' '")
sequence(f, o) = system("grep -v '^#' '".f."' | awk -F, -v o='".o."' 'NR > 1 && $3 == o && (n == 0 || $11 != p) { s = s (n++ ? \", \" : \"\") $11; p = $11 } END { print \"[\" s \"]\" }'")
# objects whose states change, with their sequences, and how many stay at 0
summary(f) = system("grep -v '^#' '".f."' | awk -F, 'NR > 1 { if (!($3 in s)) { o[++n] = $3; s[$3] = \"\" } if (!($3 in p) || $11 != p[$3]) { s[$3] = s[$3] (s[$3] == \"\" ? \"\" : \", \") $11; p[$3] = $11 } } END { for (i = 1; i <= n; i++) if (s[o[i]] == \"0\") z++; else r = r (r == \"\" ? \"\" : \"; \") o[i] \" [\" s[o[i]] \"]\"; print r (z ? \"; \" z \" others [0]\" : \"\") }'")
esc(t) = system("printf '%s' '".t."' | sed 's/_/\\\\_/g'")
base(s) = system("basename '".s."'")
state_names = "set ytics ('0 no contact' 0, '1 push at one point' 1, '2 grasp' 2, '3 push at several points' 3)"
# a spring world reports 2 for the object on the spring (handspring.h): say so
spring_state_names = "set ytics ('0 not on the spring' 0, '2 on the spring' 2)"
colors = "#1f77b4 #d62728 #2ca02c #ff7f0e #9467bd #8c564b #e377c2 #7f7f7f #bcbd22 #17becf"
color(i) = word(colors, (i - 1) % 10 + 1)

single = exists("scn")
list = single ? scn : 'hand/push_then_grasp'
do for [s in list] {
    file = traj.'/'.s.'.csv'
    objs = objects(file)
    n = words(objs)
    name = single ? 'hand_timeline_'.base(s) : 'hand_timeline'
    stats file using 1 nooutput
    frames = STATS_max
    stats file every ::n::n using 2 nooutput
    dt = STATS_max   # the t of frame 1 (rows go frame by frame, n objects each)
    if (n == 1) {    # the orientation at frame 0, for the angle turned
        stats file every ::0::0 using 7 nooutput
        q0w = STATS_max
        stats file every ::0::0 using 8 nooutput
        q0x = STATS_max
        stats file every ::0::0 using 9 nooutput
        q0y = STATS_max
        stats file every ::0::0 using 10 nooutput
        q0z = STATS_max
    }
    turned(w, x, y, z) = 2 * acos(abs(q0w * w + q0x * x + q0y * y + q0z * z) < 1 ? abs(q0w * w + q0x * x + q0y * y + q0z * z) : 1) * 180 / pi
    do for [k = 1:2] {
        if (k == 1) {
            set terminal pngcairo size 1100, 800 enhanced font "Sans,11"
            set output out.'/'.name.'.png'
        } else {
            set terminal svg size 1100, 800 enhanced font "Sans,11" background rgb "white"
            set output out.'/'.name.'.svg'
        }
        set multiplot layout 2, 1 title sprintf("Contact states (1999 paper, Fig. 12): scenario %s", esc(s)) font ",13"
        set grid
        set lmargin 24
        set rmargin 12
        set xrange [0:frames]
        set link x2 via x * dt inverse x / dt
        tstep = frames * dt <= 2.5 ? 0.25 : 0.5
        set x2tics tstep format "%.2f"
        set xtics nomirror
        set x2label "t [s]"
        set xlabel "frame"

        spring = s[1:7] eq 'spring/'
        set title (spring ? "(a) on the spring" : "(a) hand contact state") . (n > 1 ? " per object (lines offset by 0.04 each so that all show)" : "")
        flick = s eq 'hand/flick_pyramid'
        if (flick) {
            set label 11 "frame 60: the index tip pushes at one point (eq. 1-2);\nframe 61: it follows through clear of it, the pyramid flies on (eq. 3)" at 63, 1.25 font ",10"
        }
        set yrange [-0.3:3.5]
        if (spring) { eval spring_state_names } else { eval state_names }
        set ylabel "state"
        set key top right box opaque
        plot for [i = 1:n] file every n::(i - 1) using 1:($11 + 0.04 * (i - 1)) \
             with steps lw 2 lc rgb color(i) title sprintf("%s: %s", esc(word(objs, i)), sequence(file, word(objs, i)))

        unset label 11
        set title "(b) height of each object's centre G" . (n == 1 && !spring ? ", and the angle it has turned since frame 0" : "")
        if (flick) {
            set label 12 "tips over its front base edge (§4.2 rule (2)) onto a side face:\nG z = 0.0268 m, turned 180 - atan(2h/b) = 116.57 deg" at 40, 0.032 font ",10"
        }
        set ytics auto
        set autoscale y
        set ylabel "G z [m]"
        if (n == 1 && !spring) { # (a spring world's objects never turn: no torque, §4.2)
            set y2tics
            set ytics nomirror
            set y2label "turned [deg]"
            set autoscale y2
            plot file using 1:6 with lines lw 2 lc rgb color(1) title esc(word(objs, 1)).": G z", \
                 file using 1:(turned($7, $8, $9, $10)) axes x1y2 with lines lw 2 dt 2 lc rgb "#000000" title esc(word(objs, 1)).": turned since frame 0"
            unset y2tics
            unset y2label
            set ytics mirror
        } else {
            plot for [i = 1:n] file every n::(i - 1) using 1:6 with lines lw 2 lc rgb color(i) title esc(word(objs, i))
        }
        unset label 12
        unset multiplot
        unset link x2
        unset x2tics
        unset x2label
        unset lmargin
        unset rmargin
        set output
    }
}

# every hand/ scenario's states, side by side (only without scn)
if (!single) {
    cat = system("ls ".traj."/hand/*.csv 2>/dev/null | sed 's|^".traj."/||; s|\\.csv$||' | tr '\\n' ' '")
    m = words(cat)
    cols = 3
    rows = (m + cols - 1) / cols
    do for [k = 1:2] {
        if (k == 1) {
            set terminal pngcairo size 1500, 330 * rows enhanced font "Sans,10"
            set output out.'/hand_timeline_catalog.png'
        } else {
            set terminal svg size 1500, 330 * rows enhanced font "Sans,10" background rgb "white"
            set output out.'/hand_timeline_catalog.svg'
        }
        set multiplot layout rows, cols title "Contact states of the hand catalog (1999 paper, Fig. 12): 0 none, 1 push at one point, 2 grasp, 3 push at several points\n(the i-th object's line is drawn 0.04 (i - 1) higher, so that lines on the same state all show)" font ",12"
        set grid
        set yrange [-0.3:3.6]
        set ytics 0, 1, 3
        set ylabel "state"
        set xlabel "t [s]"
        set autoscale x
        set key top right opaque font ",8" samplen 2
        do for [j = 1:m] {
            s = word(cat, j)
            file = traj.'/'.s.'.csv'
            objs = objects(file)
            n = words(objs)
            set title s noenhanced
            if (n > 4) {   # many objects (the seed scene): one line each, the states in a label
                set label 1 summary(file) at graph 0.98, graph 0.92 right front font ",8" noenhanced
                unset key
                plot for [i = 1:n] file every n::(i - 1) using 2:($11 + 0.04 * (i - 1)) \
                     with steps lw 1.5 lc rgb color(i) notitle
                unset label 1
                set key top right opaque font ",8" samplen 2
            } else {
                plot for [i = 1:n] file every n::(i - 1) using 2:($11 + 0.04 * (i - 1)) \
                     with steps lw 1.5 lc rgb color(i) title sprintf("%s %s", word(objs, i), sequence(file, word(objs, i)))
            }
        }
        unset multiplot
        set output
    }
}
